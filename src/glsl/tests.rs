//! Tests of the front end as a whole: the preprocessor's expansion and conditionals, the
//! parser's precedence and statements, the messages and their positions, and piglit's GLSL
//! 1.10 and 1.20 parser tests against `tests/glsl/parse_expectations.txt`.

use super::ast::*;
use super::preprocess::{preprocess, Behavior};
use super::{compile_shader, parse_shader, InfoLog, Options, Stage};

/// The text a source preprocesses to, tokens joined by single spaces, and the log.
fn pp(source: &str) -> (String, String) {
    pp_with(source, &Options::default())
}

fn pp_with(source: &str, options: &Options) -> (String, String) {
    let mut log = InfoLog::default();
    let out = preprocess(source, options, &mut log);
    let text: Vec<String> = out.tokens.iter().map(|t| t.text.clone()).collect();
    (text.join(" "), log.text())
}

fn parse_ok(source: &str) -> TranslationUnit {
    let mut log = InfoLog::default();
    match parse_shader(source, &Options::default(), &mut log) {
        Some(p) if !log.has_errors() => p.unit,
        _ => panic!("{source}\ndid not parse:\n{}", log.text()),
    }
}

fn first_error(source: &str) -> String {
    let mut log = InfoLog::default();
    let parsed = parse_shader(source, &Options::default(), &mut log);
    assert!(parsed.is_none(), "{source}\nparsed without error");
    log.first_error().expect("an error").to_string()
}

// ---------------------------------------------------------------- preprocessor

#[test]
fn object_and_function_macros_expand_and_rescan() {
    assert_eq!(pp("#define A 1 + B\n#define B 2\nA").0, "1 + 2");
    assert_eq!(pp("#define F(x, y) ((x) * (y))\nF(a + 1, F(b, c))").0, "( ( a + 1 ) * ( ( ( b ) * ( c ) ) ) )");
    // A function-like macro's name without `(` is left alone.
    assert_eq!(pp("#define F(x) x\nF + F(1)").0, "F + 1");
    // The invocation may span lines, and rescanning reaches the text after the expansion.
    assert_eq!(pp("#define F(x) [x]\nF(\n1\n)").0, "[ 1 ]");
    assert_eq!(pp("#define G F\n#define F(x) <x>\nG(2)").0, "< 2 >");
    // No parameters, and an empty argument.
    assert_eq!(pp("#define Z() 0\n#define I(x) (x)\nZ() I()").0, "0 ( )");
}

#[test]
fn macros_do_not_recurse() {
    assert_eq!(pp("#define A A + 1\nA").0, "A + 1");
    assert_eq!(pp("#define A B\n#define B A\nA B").0, "A B");
    assert_eq!(pp("#define F(x) F(x) + x\nF(1)").0, "F ( 1 ) + 1");
    // An argument is expanded before substitution; the painted name stays unexpanded.
    assert_eq!(pp("#define f(a) a*g\n#define g(a) f(a)\nf(2)(9)").0, "2 * 9 * g");
}

#[test]
fn token_pasting_joins_and_checks_the_result() {
    assert_eq!(pp("#define CAT(a, b) a ## b\nCAT(fo, o) CAT(1, 2) CAT(, x)").0, "foo 12 x");
    let (_, log) = pp("#define CAT(a, b) a ## b\nCAT(+, /)");
    assert!(log.contains("preprocessor error: pasting `+' and `/'"), "{log}");
}

#[test]
fn predefined_macros() {
    assert_eq!(pp("__LINE__\n\n__LINE__ __FILE__ __VERSION__").0, "1 3 0 110");
    assert_eq!(pp("#version 120\n__VERSION__").0, "120");
    assert_eq!(pp("#ifdef GL_ES\nes\n#else\ndesktop\n#endif").0, "desktop");
    // __LINE__ in a macro body is the line of the invocation.
    assert_eq!(pp("#define L __LINE__\n\nL").0, "3");
    let options = Options { extensions: vec!["GL_ARB_texture_rectangle".into()] };
    assert_eq!(pp_with("GL_ARB_texture_rectangle", &options).0, "1");
}

#[test]
fn if_expressions_have_cs_precedence_and_defined() {
    let cases = [
        ("1 + 2 * 3 == 7", true),
        ("(1 + 2) * 3 == 9", true),
        ("10 - 2 - 3 == 5", true),
        ("-1 < 0 && !0", true),
        ("1 << 4 == 16 && 0x10 == 020", true),
        ("7 / 2 == 3 && 7 % 2 == 1 && -7 / 2 == -3", true),
        ("(5 & 3) == 1 && (5 | 3) == 7 && (5 ^ 3) == 6 && ~0 == -1", true),
        ("0 || 2 > 1", true),
        ("defined A && defined(B) && !defined C", true),
        ("A == 3", true),
        ("1 > 2 || 3 <= 2 || 4 >= 5", false),
    ];
    for (expr, want) in cases {
        let src = format!("#define A 3\n#define B\n#if {expr}\nyes\n#else\nno\n#endif");
        let (text, log) = pp(&src);
        assert_eq!(log, "", "{expr}");
        assert_eq!(text, if want { "yes" } else { "no" }, "{expr}");
    }
}

#[test]
fn if_errors() {
    for (expr, message) in [
        ("1 / 0", "division by zero"),
        ("1 % 0", "division by zero"),
        ("1 +", "ends early"),
        ("(1", "missing `)'"),
        ("1.0", "not an integer"),
        ("", "no expression"),
    ] {
        let (_, log) = pp(&format!("\n#if {expr}\n#endif\n"));
        assert!(log.starts_with("0:2(") && log.contains(message), "{expr}: {log}");
    }
}

#[test]
fn identifiers_in_if_that_are_no_macro_count_zero() {
    // As in C and in Mesa; the GLSL specifications call it an error (see the module doc).
    assert_eq!(pp("#if FOO\na\n#elif !FOO && BAR == 0\nb\n#endif").0, "b");
}

#[test]
fn columns_count_white_space_runs_as_one_as_mesa_does() {
    // Mesa 22 reports this at 0:3(12): the tab and the comment count one column each.
    assert_eq!(first_error("void main()\n{\n\tfloat  x   =  /* c */ ;\n}").split(':').nth(1), Some("3(12)"));
    // And after macro expansion, in the expanded text (Mesa: 0:5(17)).
    let src = "#define E (1 +\n#define F(a) a\nvoid main()\n{\n  float x = F(   E  ) ;\n}";
    assert!(first_error(src).starts_with("0:5(17): error: syntax error, unexpected ';'"), "{}", first_error(src));
}

#[test]
fn conditionals_nest_and_skip() {
    let src = "#if 0\n#if 1\na\n#else\nb\n#endif\n#elif 1\nc\n#elif 1\nd\n#else\ne\n#endif\n\
               #ifdef X\nf\n#elif 1 / 0 == 0\ng\n#endif\n#ifndef X\nh\n#endif";
    // The #elif after a skipped #ifdef group is evaluated (and fails): only c, then h.
    let (text, log) = pp(src);
    assert!(log.contains("division by zero"), "{log}");
    assert_eq!(text, "c h");
    // Skipped sections ignore bad directives and stray characters.
    assert_eq!(pp("#if 0\n#bogus\n$ \" @\n#error no\n#endif\nok"), ("ok".to_string(), String::new()));
}

#[test]
fn conditional_errors_name_their_line() {
    // Mesa reports an unterminated #if, and errors in #if expressions, at the end of its line.
    assert_eq!(pp("a\n#if 1\nb\n").1, "0:2(6): preprocessor error: Unterminated #if\n");
    assert_eq!(pp("#if 1/0\n#endif").1, "0:1(8): preprocessor error: division by zero in #if (`/' by 0)\n");
    assert_eq!(pp("#endif").1, "0:1(1): preprocessor error: #endif without #if\n");
    assert!(pp("#if 1\n#else\n#else\n#endif").1.contains("#else after #else"));
    assert!(pp("#if 1\n#else\n#elif 1\n#endif").1.contains("#elif after #else"));
    assert!(pp("#elif 1").1.contains("#elif without #if"));
    assert!(pp("#foo").1.contains("invalid directive `#foo'"));
}

#[test]
fn defines_check_names_and_redefinitions() {
    assert_eq!(pp("#define A 1\n#define A 1 \n#define F(x) x+1\n#define F(x) x+1\nA").1, "");
    assert!(pp("#define A 1\n#define A 2").1.contains("0:2(9): preprocessor error: Redefinition of macro `A'"));
    assert!(pp("#define A 1+1\n#define A 1 + 1").1.contains("Redefinition"));
    assert!(pp("#define F(x) x\n#define F(y) y").1.contains("Redefinition"));
    assert!(pp("#define GL_FOO 1").1.contains("preprocessor error: macro names starting with `GL_'"));
    assert!(pp("#undef __LINE__").1.contains("preprocessor error: predefined macro `__LINE__'"));
    let log = pp("#define a__b 1").1;
    assert!(log.contains("warning") && !log.contains("error"), "{log}");
    assert!(pp("#define F(x, x) x").1.contains("duplicate macro parameter"));
    assert!(pp("#define S(a) #a").1.contains("stringification"));
    assert!(pp("#define F(a) a\nF(1, 2)").1.contains("invoked with 2 arguments (1 expected)"));
    assert!(pp("#define F(a) a\nF(1").1.contains("unterminated invocation"));
    assert_eq!(pp("#define A 1\n#undef A\nA").0, "A");
}

#[test]
fn version_must_come_first_and_be_supported() {
    assert_eq!(pp("/* c */ // c\n  #version 120\n").1, "");
    assert!(pp("int x;\n#version 120").1.contains("0:2(1): error: #version must be the first"));
    assert!(pp("#define A\n#version 120").1.contains("#version must be the first"));
    assert!(pp("#version 130").1.contains("0:1(1): error: GLSL 1.30 is not supported"));
    assert!(pp("#version 100").1.contains("GLSL ES 1.00 is not supported"));
    assert!(pp("#version 300 es").1.contains("GLSL ES 3.00 is not supported"));
    assert!(pp("#version 120 core").1.contains("no profile"));
    assert!(pp("#version 18446744073709551615").1.contains("invalid version number"));
    // No macro expansion on a #version line.
    assert!(pp("#define V 120\n#version V").1.contains("error"));
}

#[test]
fn line_sets_the_next_lines_number_and_source() {
    // GLSL 1.10/1.20: after `#line 10`, the next line is 11.
    let (text, log) = pp("#line 10\n__LINE__\n#line 20 3\n__LINE__ __FILE__\n#error here");
    assert_eq!(text, "11 21 3");
    assert_eq!(log, "3:22(1): preprocessor error: #error here\n");
    let mut log = InfoLog::default();
    parse_shader("#line 41 2\nvoid main() { x = ; }", &Options::default(), &mut log);
    assert!(log.text().starts_with("2:42(19): error: syntax error"), "{}", log.text());
}

#[test]
fn extensions_are_recorded_and_checked() {
    let mut log = InfoLog::default();
    let options = Options { extensions: vec!["GL_ARB_draw_buffers".into()] };
    let out = preprocess("#extension GL_ARB_draw_buffers : enable\n#extension all : warn\n", &options, &mut log);
    assert_eq!(log.text(), "");
    assert_eq!(out.extensions.len(), 2);
    assert_eq!(out.extensions[0].behavior, Behavior::Enable);
    assert!(pp("#extension GL_FOO_bar : require").1.contains("error: extension `GL_FOO_bar' unsupported"));
    let log = pp("#extension GL_FOO_bar : enable").1;
    assert!(log.contains("warning") && !log.contains("error"));
    assert!(pp("#extension all : enable").1.contains("error"));
    assert!(pp("#extension all : require").1.contains("error"));
    assert!(pp("#extension GL_FOO_bar : enable;").1.contains("error: syntax error in #extension"));
    assert!(pp("#define B disable\n#extension all : B").1.contains("unknown extension behavior `B'"));
}

#[test]
fn pragmas_are_ignored_but_invariant_all_is_recorded() {
    let mut log = InfoLog::default();
    let out = preprocess("#pragma optimize(off)\n#pragma STDGL invariant(all)\nx", &Options::default(), &mut log);
    assert_eq!(log.text(), "");
    assert!(out.invariant_all);
}

#[test]
fn expansion_is_bounded() {
    // Each level doubles the text: 2^30 tokens unless the budget stops it.
    let mut src = String::from("#define L0 x x\n");
    for i in 1..=30 {
        src.push_str(&format!("#define L{i} L{} L{}\n", i - 1, i - 1));
    }
    src.push_str("L30\n");
    assert!(pp(&src).1.contains("exceeds the implementation's limit"));
}

// ---------------------------------------------------------------- parser

fn main_body(unit: &TranslationUnit) -> &[Statement] {
    match unit.items.last() {
        Some(ExternalDeclaration::Function(f)) => &f.body,
        other => panic!("no function last: {other:?}"),
    }
}

/// An expression written back with full parentheses.
fn show(e: &Expr) -> String {
    use ExprKind::*;
    match &e.kind {
        Ident(n) => n.clone(),
        Int(v) => v.to_string(),
        Float(v) => format!("{v:?}"),
        Bool(b) => b.to_string(),
        Unary(op, a) => match op {
            UnaryOp::PostIncrement => format!("({}++)", show(a)),
            UnaryOp::PostDecrement => format!("({}--)", show(a)),
            UnaryOp::PreIncrement => format!("(++{})", show(a)),
            UnaryOp::PreDecrement => format!("(--{})", show(a)),
            UnaryOp::Plus => format!("(+{})", show(a)),
            UnaryOp::Minus => format!("(-{})", show(a)),
            UnaryOp::Not => format!("(!{})", show(a)),
            UnaryOp::BitNot => format!("(~{})", show(a)),
        },
        Binary(op, a, b) => format!("({} {op:?} {})", show(a), show(b)),
        Assign(op, a, b) => format!("({} ={op:?} {})", show(a), show(b)),
        Conditional(c, a, b) => format!("({} ? {} : {})", show(c), show(a), show(b)),
        Sequence(a, b) => format!("({}, {})", show(a), show(b)),
        Index(a, i) => format!("{}[{}]", show(a), show(i)),
        Field(a, f) => format!("{}.{f}", show(a)),
        Call(Callee::Name(n), args) => format!("{n}({})", args.iter().map(show).collect::<Vec<_>>().join(", ")),
        Call(Callee::Type(t), args) => {
            format!(
                "{:?}{}({})",
                t.name,
                if t.array.is_some() { "[]" } else { "" },
                args.iter().map(show).collect::<Vec<_>>().join(", ")
            )
        }
        Method(a, m, args) => format!("{}.{m}({})", show(a), args.iter().map(show).collect::<Vec<_>>().join(", ")),
    }
}

fn expr(source: &str) -> String {
    let unit = parse_ok(&format!("#version 120\nvoid main() {{ {source}; }}"));
    match &main_body(&unit)[0].kind {
        StatementKind::Expr(Some(e)) => show(e),
        other => panic!("{other:?}"),
    }
}

#[test]
fn precedence_and_associativity() {
    assert_eq!(expr("a + b * c"), "(a Add (b Mul c))");
    assert_eq!(expr("a - b - c"), "((a Sub b) Sub c)");
    assert_eq!(expr("a / b * c"), "((a Div b) Mul c)");
    assert_eq!(expr("a < b == c > d"), "((a Less b) Equal (c Greater d))");
    assert_eq!(expr("a || b ^^ c && d"), "(a Or (b Xor (c And d)))");
    assert_eq!(expr("a | b ^ c & d"), "(a BitOr (b BitXor (c BitAnd d)))");
    assert_eq!(expr("a << 1 + 2"), "(a Shl (1 Add 2))");
    assert_eq!(expr("a = b = c"), "(a =None (b =None c))");
    assert_eq!(expr("a += b * c"), "(a =Some(Add) (b Mul c))");
    assert_eq!(expr("a ? b : c ? d : e"), "(a ? b : (c ? d : e))");
    assert_eq!(expr("a ? b, c : d = e"), "(a ? (b, c) : (d =None e))");
    assert_eq!(expr("x = a ? b : c"), "(x =None (a ? b : c))");
    assert_eq!(expr("a, b = c, d"), "((a, (b =None c)), d)");
    assert_eq!(expr("-a * -b"), "((-a) Mul (-b))");
    assert_eq!(expr("!a && !!b"), "((!a) And (!(!b)))");
    assert_eq!(expr("-x++"), "(-(x++))");
    assert_eq!(expr("++x[1].y"), "(++x[1].y)");
    assert_eq!(expr("(a + b) * c"), "((a Add b) Mul c)");
    assert_eq!(expr("(a) = b"), "(a =None b)");
}

#[test]
fn postfix_calls_constructors_and_swizzles() {
    assert_eq!(expr("v.xyz.x"), "v.xyz.x");
    assert_eq!(expr("m[1][2]"), "m[1][2]");
    assert_eq!(expr("f(a, b)[0].w"), "f(a, b)[0].w");
    assert_eq!(expr("f()"), "f()");
    assert_eq!(expr("f(void)"), "f()");
    assert_eq!(expr("vec4(1.0, 2, true, false)"), "Vec(4)(1.0, 2, true, false)");
    assert_eq!(expr("mat2x3(1.0)"), "Mat(2, 3)(1.0)");
    assert_eq!(expr("float[3](1.0, 2.0, 3.0)"), "Float[](1.0, 2.0, 3.0)");
    assert_eq!(expr("float[](1.0).length()"), "Float[](1.0).length()");
    assert_eq!(expr("a.length()"), "a.length()");
    assert_eq!(expr("x--"), "(x--)");
    assert_eq!(expr("0x10 + 010 + 1e1"), "((16 Add 8) Add 10.0)");
}

#[test]
fn every_statement_kind() {
    let unit = parse_ok(
        "void main() {\n\
           int i = 0, j[2];\n\
           { i = 1; }\n\
           ;\n\
           if (i > 0) i = 2; else { i = 3; }\n\
           for (int k = 0; k < 4; ++k) { if (k == 2) continue; else break; }\n\
           for (;;) break;\n\
           while (bool b = i < 3) i++;\n\
           do i--; while (i > 0);\n\
           if (i == 5) discard;\n\
           return;\n\
         }",
    );
    let kinds: Vec<&str> = main_body(&unit)
        .iter()
        .map(|s| match &s.kind {
            StatementKind::Declaration(_) => "decl",
            StatementKind::Compound(_) => "compound",
            StatementKind::Expr(None) => "empty",
            StatementKind::Expr(Some(_)) => "expr",
            StatementKind::If { otherwise: Some(_), .. } => "if-else",
            StatementKind::If { .. } => "if",
            StatementKind::For { condition: None, .. } => "for-forever",
            StatementKind::For { .. } => "for",
            StatementKind::While { condition: Condition::Declaration { .. }, .. } => "while-decl",
            StatementKind::While { .. } => "while",
            StatementKind::DoWhile { .. } => "do",
            StatementKind::Return(_) => "return",
            StatementKind::Break | StatementKind::Continue | StatementKind::Discard => "jump",
        })
        .collect();
    assert_eq!(
        kinds,
        ["decl", "compound", "empty", "if-else", "for", "for-forever", "while-decl", "do", "if", "return"]
    );
    assert_eq!(main_body(&unit)[4].pos.line, 6);
}

#[test]
fn declarations_with_qualifiers_structs_and_arrays() {
    let unit = parse_ok(
        "#version 120\n\
         attribute vec4 pos;\n\
         uniform mat4 mvp, m[2];\n\
         centroid varying vec2 uv;\n\
         invariant centroid varying vec3 n;\n\
         invariant varying float f;\n\
         invariant gl_Position, n;\n\
         const float k = 1.0, ks[] = float[](1.0, 2.0);\n\
         float[3] a3;\n\
         struct S { vec3 p; float w[2], v; } s1, s2[2];\n\
         S make(in float x, out S o, inout vec4 io[2], const int c);\n\
         float unnamed(float, vec2);\n\
         S make(in float x, out S o, inout vec4 io[2], const int c) { S t = S(vec3(x), float[2](1.0, 2.0), x); return t; }\n\
         void main() { S s; s.p = vec3(1.0); gl_Position = mvp * pos; }",
    );
    assert_eq!(unit.items.len(), 13);
    let ExternalDeclaration::Declaration(Declaration::Variables { ty, .. }) = &unit.items[3] else { panic!() };
    assert!(ty.qualifiers.invariant && ty.qualifiers.centroid && ty.qualifiers.storage == Some(Storage::Varying));
    let ExternalDeclaration::Declaration(Declaration::Invariant { names, .. }) = &unit.items[5] else { panic!() };
    assert_eq!(names.iter().map(|n| n.0.as_str()).collect::<Vec<_>>(), ["gl_Position", "n"]);
    let ExternalDeclaration::Declaration(Declaration::Variables { ty, declarators, .. }) = &unit.items[8] else {
        panic!()
    };
    let TypeName::Struct(def) = &ty.specifier.name else { panic!() };
    assert_eq!((def.name.as_deref(), def.members.len(), declarators.len()), (Some("S"), 2, 2));
    let ExternalDeclaration::Declaration(Declaration::Prototype(p)) = &unit.items[9] else { panic!() };
    let dirs: Vec<_> = p.parameters.iter().map(|p| (p.direction, p.is_const)).collect();
    use ParameterDirection::*;
    assert_eq!(dirs, [(Some(In), false), (Some(Out), false), (Some(Inout), false), (None, true)]);
}

#[test]
fn struct_names_are_types_in_their_scope_only() {
    // The built-in state's struct types are types from the start.
    parse_ok("vec4 f(gl_LightSourceParameters l) { gl_MaterialParameters m = gl_FrontMaterial; return l.ambient; }");
    // A variable may hide a struct name in an inner scope; then `S x;` is an error there.
    parse_ok("struct S { float f; };\nvoid main() { S a; { float S; S = 1.0; } S b; }");
    let e = first_error("struct S { float f; };\nvoid main() { float S; S b; }");
    assert_eq!(e, "0:2(26): error: syntax error, unexpected IDENTIFIER `b', expecting ';'");
}

#[test]
fn version_gating_of_120_syntax() {
    assert!(first_error("float[3] a;").contains("require GLSL 1.20"));
    assert!(first_error("void main() { float a[2] = float[2](1.0, 2.0); }").contains("require GLSL 1.20"));
    // The `f` suffix is 1.20's; Mesa compiles it in 1.10 with a warning, and so does tessera.
    let mut log = InfoLog::default();
    assert!(parse_shader("void main() { float x = 1.0f; }", &Options::default(), &mut log).is_some());
    assert_eq!(log.text(), "0:1(25): warning: floating-point suffix in `1.0f' is not valid in GLSL 1.10\n");
    // 1.20's keywords are identifiers in 1.10.
    parse_ok("float invariant, centroid; void main() { float mat2x3 = invariant; }");
    assert!(first_error("invariant gl_Position;").contains("syntax error"));
    assert!(first_error("#version 120\nfloat invariant;").contains("syntax error, unexpected `invariant'"));
    // Precision words are reserved in 1.20, not in 1.10.
    parse_ok("float highp; void main() {}");
    assert!(first_error("#version 120\nfloat highp;").contains("illegal use of reserved word `highp'"));
}

#[test]
fn syntax_errors_name_the_token_and_position() {
    assert_eq!(
        first_error("void main()\n{\n  x = ;\n}"),
        "0:3(6): error: syntax error, unexpected ';', expecting an expression"
    );
    assert_eq!(
        first_error("void main() { a + b = c; }"),
        "0:1(21): error: syntax error, unexpected '=', expecting ';'"
    );
    assert_eq!(first_error("void main() {"), "0:1(14): error: syntax error, unexpected end of file, expecting '}'");
    assert_eq!(first_error("void main() { int goto; }"), "0:1(19): error: illegal use of reserved word `goto'");
    assert_eq!(first_error("void main() { int i = 08; }"), "0:1(23): error: invalid octal integer literal `08'");
    assert_eq!(first_error("void main() <% }"), "0:1(13): error: syntax error, unexpected '<', expecting ';'");
    assert!(first_error("void main() { int i = \"1\"; }").contains("unexpected character `\"'"));
    assert!(first_error("uniform invariant vec4 v;").contains("syntax error"));
    assert!(first_error("#version 120\ninvariant uniform vec4 v;").contains("expecting `varying'"));
    assert!(first_error("in vec4 v;").contains("syntax error"));
    assert!(first_error("void f() { void g() {} }").contains("unexpected '{'"));
    assert!(first_error("struct S {};").contains("expecting a type"));
    // Errors in a macro's expansion point at the invocation.
    assert_eq!(
        first_error("#define BAD )\nvoid main() {\n  float x = BAD;\n}"),
        "0:3(12): error: syntax error, unexpected ')', expecting an expression"
    );
}

#[test]
fn preprocessor_errors_stop_before_parsing() {
    let mut log = InfoLog::default();
    assert!(parse_shader("#error one\n#error two\nvoid main( {", &Options::default(), &mut log).is_none());
    assert_eq!(log.text(), "0:1(1): preprocessor error: #error one\n0:2(1): preprocessor error: #error two\n");
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    for (open, close) in [("(", ")"), ("-", ""), ("{", "}")] {
        let n = 5000;
        let body = format!("{}1{}", open.repeat(n), close.repeat(n));
        let src =
            if open == "{" { format!("void main() {body}") } else { format!("void main() {{ float x = {body}; }}") };
        let src = src.replace("{1}", "{;}");
        assert!(first_error(&src).contains("nesting deeper than"), "{open}");
    }
    // Nesting below the ceiling parses.
    parse_ok(&format!("void main() {{ float x = {}1.0{}; }}", "(".repeat(200), ")".repeat(200)));
}

/// Chains that grow the tree to the left without nesting (10⁵ terms overflowed the stack
/// when the tree was checked and freed) are refused past their ceiling, on this thread's
/// stack; a long but bounded chain compiles.
#[test]
fn long_operator_chains_are_an_error_not_a_crash() {
    let n = 100_000;
    for (what, source) in [
        ("sum", format!("void main() {{ float a = 1.0; gl_FragColor = vec4({}); }}", vec!["a"; n].join("+"))),
        ("sequence", format!("void main() {{ float a = 1.0; a = ({}); }}", vec!["a"; n].join(","))),
        ("swizzles", format!("void main() {{ vec4 a = vec4(1.0); a.x = a{}; }}", ".xxxx".repeat(n))),
    ] {
        let mut log = InfoLog::default();
        let checked = super::compile_shader(&source, super::Stage::Fragment, &Options::default(), &mut log);
        assert!(checked.is_none(), "{what}");
        assert!(log.text().contains("operators in a row"), "{what}: {}", log.text());
    }
    let sum = vec!["a"; 512].join("+");
    let mut log = InfoLog::default();
    let source = format!("void main() {{ float a = 1.0; gl_FragColor = vec4({sum}); }}");
    assert!(
        super::compile_shader(&source, super::Stage::Fragment, &Options::default(), &mut log).is_some(),
        "{}",
        log.text()
    );
}

/// The whole front end (compile, link, lowering) on a thread of 2 MB, Rust's default for a
/// spawned thread, at the bounds: the longest chain (piglit's `op-selection-*`: 511 `+`
/// inside a constructor) compiles, and so does a chain under 100 levels of nesting; a
/// chain under 200 levels passes [`super::check::MAX_DEPTH`] and is an error, not an
/// overflow.
#[test]
fn chains_at_the_bounds_compile_on_a_small_stack() {
    let run = |source: String| {
        std::thread::Builder::new()
            .stack_size(2 << 20)
            .spawn(move || {
                let mut log = InfoLog::default();
                let checked = compile_shader(&source, Stage::Fragment, &Options::default(), &mut log);
                let Some(checked) = checked else { return Err(log.text()) };
                let checked = std::sync::Arc::new(checked);
                super::link::link(std::slice::from_ref(&checked), &[])?;
                super::lower::lower(&[&checked]).map(|_| ())
            })
            .unwrap()
            .join()
            .unwrap()
    };
    let chain = vec!["u[0]"; 512].join(" + ");
    let nested = |levels: usize| {
        format!(
            "#version 120\nuniform float u[2];\nvoid main() {{ gl_FragColor = vec4({}{chain}{}); }}",
            "u[1] * (".repeat(levels),
            ")".repeat(levels)
        )
    };
    run(nested(0)).unwrap();
    run(nested(100)).unwrap();
    assert!(run(nested(200)).unwrap_err().contains("expression nesting deeper than 640 levels"));
    let lengths: Vec<String> = (0..512).map(|i| format!("a{i}.length()")).collect();
    let arrays: String = (0..512).map(|i| format!("float a{i}[1];")).collect();
    let source = format!("#version 120\nvoid main() {{ {arrays} gl_FragColor = vec4({}); }}", lengths.join(" + "));
    run(source).unwrap();
}

// ---------------------------------------------------------------- piglit

/// One piglit parser test: its path under the spec directory and its expected result.
struct PiglitTest {
    name: String,
    source: String,
    expect_pass: bool,
}

fn piglit_tests(root: &std::path::Path) -> Vec<PiglitTest> {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "vert" || x == "frag") {
                out.push(p);
            }
        }
    }
    let mut tests = Vec::new();
    for version in ["glsl-1.10", "glsl-1.20"] {
        let mut files = Vec::new();
        walk(&root.join(version), &mut files);
        files.sort();
        for f in files {
            let Ok(source) = std::fs::read_to_string(&f) else { continue };
            let config: String = source.split("[end config]").next().unwrap_or("").to_string();
            let field = |key: &str| {
                config.lines().find_map(|l| l.split_once(key).map(|(_, v)| v.trim().to_string())).unwrap_or_default()
            };
            // Only tests of GLSL 1.10 and 1.20 (one 1.20 directory holds a 1.50 test).
            if !matches!(field("glsl_version:").as_str(), "1.10" | "1.20") {
                continue;
            }
            let expect_pass = match field("expect_result:").as_str() {
                "pass" => true,
                "fail" => false,
                _ => continue,
            };
            let name = f.strip_prefix(root).unwrap_or(&f).display().to_string();
            tests.push(PiglitTest { name, source, expect_pass });
        }
    }
    tests
}

/// piglit's glslparser tests of GLSL 1.10 and 1.20, compiled (preprocessor, parser and
/// semantic analysis) for the stage their extension names: every `pass` test must compile
/// and every `fail` test must be refused, unless `tests/glsl/parse_expectations.txt` lists
/// it, with the reason tessera's result differs. The test fails when a result differs from
/// the list either way, so that the list stays true. Without piglit it skips, except under
/// CI (CI=true).
#[test]
fn piglit_glsl_110_120_parser_tests() {
    let root = std::path::Path::new("/usr/lib/x86_64-linux-gnu/piglit/tests/spec");
    if !root.join("glsl-1.10").is_dir() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "piglit's GLSL tests are not installed at {}",
            root.display()
        );
        println!("skipped: piglit's GLSL tests are not installed at {}", root.display());
        return;
    }
    let list_path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/glsl/parse_expectations.txt");
    let list = std::fs::read_to_string(&list_path).unwrap_or_else(|e| panic!("{}: {e}", list_path.display()));
    let mut expected_to_differ = std::collections::BTreeMap::new();
    for line in list.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')) {
        let (name, reason) = line.split_once(char::is_whitespace).unwrap_or((line, ""));
        expected_to_differ.insert(name.to_string(), reason.trim().to_string());
    }
    let tests = piglit_tests(root);
    assert!(tests.len() > 300, "only {} piglit tests found", tests.len());
    let mut problems = Vec::new();
    let (mut pass_agree, mut fail_agree, mut differ) = (0, 0, 0);
    let mut seen = std::collections::BTreeSet::new();
    for t in &tests {
        let mut log = InfoLog::default();
        let compiled = compile_shader(&t.source, piglit_stage(&t.name), &Options::default(), &mut log).is_some();
        let listed = expected_to_differ.contains_key(&t.name);
        if listed {
            seen.insert(t.name.clone());
        }
        let agrees = compiled == t.expect_pass;
        match (agrees, listed) {
            (true, false) if compiled => pass_agree += 1,
            (true, false) => fail_agree += 1,
            (false, true) => differ += 1,
            (true, true) => problems.push(format!("{}: listed as differing, agrees with piglit now", t.name)),
            (false, false) if t.expect_pass => {
                problems.push(format!("{}: expected to compile, but:\n{}", t.name, log.text()))
            }
            (false, false) => problems.push(format!("{}: expected to fail, compiles (list it with a reason?)", t.name)),
        }
    }
    for name in expected_to_differ.keys().filter(|n| !seen.contains(*n)) {
        problems.push(format!("{name}: listed but not among piglit's tests"));
    }
    println!(
        "piglit GLSL 1.10/1.20 parser tests: {} in all; {pass_agree} pass tests compile, {fail_agree} fail tests \
         are refused, {differ} differ (listed)",
        tests.len()
    );
    assert!(problems.is_empty(), "{} differences:\n{}", problems.len(), problems.join("\n"));
}

/// The stage of a piglit shader file: `.vert` or `.frag`.
fn piglit_stage(name: &str) -> Stage {
    if name.ends_with(".vert") {
        Stage::Vertex
    } else {
        Stage::Fragment
    }
}

/// Prints each piglit test with its verdict and first error message (run by hand:
/// `cargo test --release --lib glsl::tests::list_refused -- --ignored --nocapture`).
#[test]
#[ignore]
fn list_refused() {
    let root = std::path::Path::new("/usr/lib/x86_64-linux-gnu/piglit/tests/spec");
    for t in piglit_tests(root) {
        let mut log = InfoLog::default();
        let compiled = compile_shader(&t.source, piglit_stage(&t.name), &Options::default(), &mut log).is_some();
        let verdict = match (t.expect_pass, compiled) {
            (true, true) => "pass-agree",
            (false, false) => "fail-agree",
            (true, false) => "DIFFER(refused)",
            (false, true) => "DIFFER(compiles)",
        };
        println!("{verdict} {}: {}", t.name, log.first_error().map(|d| d.to_string()).unwrap_or_default());
    }
}

/// Where Debian's piglit package keeps its tests.
pub(in crate::glsl) const PIGLIT_SPEC: &str = "/usr/lib/x86_64-linux-gnu/piglit/tests/spec";

/// The `.shader_test` files under piglit's `tests/spec/<dir>` for each of `dirs`, sorted;
/// `None` (the test skips, saying so) when piglit is not installed, except under CI, where
/// a missing reference is a failure.
pub(in crate::glsl) fn piglit_shader_tests(dirs: &[&str]) -> Option<Vec<std::path::PathBuf>> {
    let root = std::path::Path::new(PIGLIT_SPEC);
    if !root.join("glsl-1.10").is_dir() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "piglit's GLSL tests are not installed at {}",
            root.display()
        );
        println!("skipped: piglit's GLSL tests are not installed at {}", root.display());
        return None;
    }
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "shader_test") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    for dir in dirs {
        walk(&root.join(dir), &mut files);
    }
    files.sort();
    Some(files)
}

/// The vertex and fragment shaders of piglit's GLSL 1.10 and 1.20 execution tests
/// (`.shader_test`): valid programs that Mesa runs, so every one must compile for its stage
/// (shaders that enable an extension are left out: tessera's front end knows none yet).
/// Skips without piglit, except under CI.
#[test]
fn piglit_glsl_110_120_execution_shaders_parse() {
    let Some(files) = piglit_shader_tests(&["glsl-1.10", "glsl-1.20"]) else { return };
    let root = std::path::Path::new(PIGLIT_SPEC);
    let (mut parsed, mut failures) = (0, Vec::new());
    let (mut lowered, mut not_lowered) = (0, Vec::<String>::new());
    for f in &files {
        let Ok(text) = std::fs::read_to_string(f) else { continue };
        // shader_runner puts `#version 120` before a shader without one when the test
        // requires GLSL 1.20.
        let requires_120 = text.lines().any(|l| l.split_whitespace().collect::<Vec<_>>() == ["GLSL", ">=", "1.20"]);
        let mut section: Option<(String, String)> = None;
        let mut shaders = Vec::new();
        for line in text.lines().chain(std::iter::once("[end]")) {
            if line.starts_with('[') {
                if let Some(s) = section.take() {
                    shaders.push(s);
                }
                if line.trim() == "[vertex shader]" || line.trim() == "[fragment shader]" {
                    section = Some((line.trim().to_string(), String::new()));
                }
            } else if let Some((_, body)) = &mut section {
                body.push_str(line);
                body.push('\n');
            }
        }
        for (kind, source) in shaders {
            let newer = source.lines().any(|l| {
                let l = l.trim_start();
                l.starts_with("#extension") || (l.starts_with("#version") && !l.contains("110") && !l.contains("120"))
            });
            if newer {
                continue;
            }
            // Uses min(int, int), which GLSL 1.30 brings, in a GLSL 1.10 shader.
            if f.ends_with("glsl-1.10/execution/vs-loop-variable-iteration-limit-unroll.shader_test") {
                continue;
            }
            let has_version = source.lines().any(|l| l.trim_start().starts_with("#version"));
            let source = if requires_120 && !has_version { format!("#version 120\n{source}") } else { source };
            let mut log = InfoLog::default();
            let stage = if kind == "[vertex shader]" { Stage::Vertex } else { Stage::Fragment };
            if let Some(checked) = compile_shader(&source, stage, &Options::default(), &mut log) {
                parsed += 1;
                // Every shader that compiles also lowers onto the IR (and validates), alone
                // (a test's other stage does not matter to the lowering).
                let name = f.strip_prefix(root).unwrap_or(f).display().to_string();
                match std::panic::catch_unwind(|| super::lower::lower(&[&checked])) {
                    Ok(Ok(_)) => lowered += 1,
                    // A shader that calls a function defined in another shader of its stage.
                    Ok(Err(e)) if e.contains("has no definition") || e.contains("no definition of `main'") => {
                        lowered += 1
                    }
                    Ok(Err(e)) => not_lowered.push(format!("{name} {kind}: {e}\n")),
                    Err(_) => not_lowered.push(format!("{name} {kind}: panic\n")),
                }
            } else {
                failures.push(format!("{} {kind}: {}", f.strip_prefix(root).unwrap_or(f).display(), log.text()));
            }
        }
    }
    println!("piglit GLSL 1.10/1.20 execution shaders: {parsed} parse, {} refused", failures.len());
    println!("{lowered} lower, {} do not:\n{}", not_lowered.len(), not_lowered.join(""));
    // Only the two tests of 2⁶⁴ nested calls stay refused: every call is inlined (they need
    // calls in the IR).
    assert!(not_lowered.iter().all(|f| f.contains("inline-explosion")), "{}", not_lowered.join(""));
    assert!(lowered >= 1420, "only {lowered} lower");
    assert!(parsed > 1000, "only {parsed} shaders found");
    assert!(failures.is_empty(), "{} shaders refused:\n{}", failures.len(), failures.join(""));
}

/// GLSL 1.10's constant expressions have no function calls (1.10 section 5.10; 1.20 adds
/// the built-ins): a built-in call in a `const` initializer or an array size is refused in
/// 1.10, as Mesa refuses it (piglit's glslparsertest/glsl2/const-builtin-110.frag), wherever
/// it sits in the expression, and accepted in 1.20. A built-in call elsewhere in 1.10 (an
/// ordinary initializer, beside a `const` declaration) compiles and leaves the next `const`
/// declaration alone.
#[test]
fn builtin_calls_are_constant_expressions_from_glsl_120_on() {
    let compile = |source: &str| {
        let mut log = InfoLog::default();
        let checked = compile_shader(source, Stage::Fragment, &Options::default(), &mut log);
        // The message without its position.
        let message = |e: String| e.split_once("error: ").map_or(e.clone(), |(_, m)| m.to_string());
        checked.map(|_| ()).ok_or_else(|| message(log.first_error().expect("an error").to_string()))
    };
    let body = |version: u32, statements: &str| {
        format!("#version {version}\nuniform float u;\nvoid main() {{\n{statements}\n  gl_FragColor = vec4(u);\n}}\n")
    };
    assert_eq!(
        compile(&body(110, "  const float one = abs(-1.0);")),
        Err("initializer of const variable `one' must be a constant expression".to_string())
    );
    assert_eq!(
        compile(&body(110, "  const vec2 v = vec2(1.0, 2.0 * sqrt(4.0));")),
        Err("initializer of const variable `v' must be a constant expression".to_string())
    );
    assert_eq!(
        compile(&body(110, "  float a[int(abs(-2.0))];")),
        Err("array size must be a constant valued expression".to_string())
    );
    assert_eq!(
        compile(&body(110, "  float x = abs(-1.0) + u;\n  const float k = 2.0 * 3.0;\n  float a[int(k)];")),
        Ok(())
    );
    assert_eq!(compile(&body(110, "  const float k = float(ivec2(3, 4).y) - 1.0;")), Ok(()));
    assert_eq!(
        compile(&body(120, "  const float one = abs(-1.0);\n  const vec2 v = vec2(1.0, 2.0 * sqrt(4.0));")),
        Ok(())
    );
    assert_eq!(compile(&body(120, "  float a[int(abs(-2.0))];")), Ok(()));
}

/// Times the front end on a 100 000-line shader and a 200-line one (run by hand:
/// `cargo test --release --lib glsl::tests::front_end_timing -- --ignored --nocapture`).
#[test]
#[ignore]
fn front_end_timing() {
    for lines in [200, 100_000] {
        let mut src =
            String::from("#version 120\n#define SQ(x) ((x) * (x))\nuniform vec4 u;\nvoid main() {\n  vec4 a = u;\n");
        for i in 0..lines {
            src.push_str(&format!("  a.x += SQ(a.y * {i}.0 + u.z) - float({i}) / (1.0 + a.w); // line {i}\n"));
        }
        src.push_str("  gl_FragColor = a;\n}\n");
        let start = std::time::Instant::now();
        let mut log = InfoLog::default();
        assert!(parse_shader(&src, &Options::default(), &mut log).is_some(), "{}", log.text());
        let parsed = start.elapsed();
        let start = std::time::Instant::now();
        assert!(compile_shader(&src, Stage::Fragment, &Options::default(), &mut log).is_some(), "{}", log.text());
        let compiled = start.elapsed();
        println!(
            "{lines} lines: parse {parsed:?} ({:.2} µs/line), whole compile {compiled:?} ({:.2} µs/line)",
            parsed.as_secs_f64() * 1e6 / lines as f64,
            compiled.as_secs_f64() * 1e6 / lines as f64
        );
    }
}

/// The shader of [`front_end_stack`]: `depth` levels of one kind of nesting in one
/// expression (`sum`: a left-deep chain of `+`; the others nest to the right).
fn nested_shader(shape: &str, depth: usize) -> String {
    let expr = match shape {
        "sum" => vec!["a"; depth + 1].join(" + "),
        "neg" => format!("{}a{}", "-(".repeat(depth), ")".repeat(depth)),
        "call" => format!("{}a{}", "sin(".repeat(depth), ")".repeat(depth)),
        "user" => format!("{}a{}", "f(".repeat(depth), ")".repeat(depth)),
        "construct" => format!("{}a{}", "float(".repeat(depth), ")".repeat(depth)),
        "right" => format!("{}a{}", "a * (".repeat(depth), ")".repeat(depth)),
        "conditional" => format!("{}a{}", "b ? a : (".repeat(depth), ")".repeat(depth)),
        "index" => format!("v[{}0{}]", "i[".repeat(depth), "]".repeat(depth)),
        "assign" => format!("{}a", "a = ".repeat(depth)),
        "and" => format!("float({})", vec!["b"; depth + 1].join(" && ")),
        _ => panic!("shape {shape}"),
    };
    format!(
        "#version 120\nuniform float a; uniform bool b; uniform int i[4]; uniform float v[4];\n\
         float f(float x) {{ return x * 2.0; }}\n\
         void main() {{ float a = a; gl_FragColor = vec4({expr}); }}\n"
    )
}

/// Runs the whole front end (compile, link, lowering, freeing) on a thread of
/// `GFRONT_STACK` bytes for the shader of `GFRONT_SHAPE` nested `GFRONT_DEPTH` deep (run by
/// hand, one process per size, to find the stack each level costs: an overflow aborts).
#[test]
#[ignore]
fn front_end_stack() {
    let var = |n: &str| std::env::var(n).unwrap_or_else(|_| panic!("{n}"));
    let stack: usize = var("GFRONT_STACK").parse().unwrap();
    let depth: usize = var("GFRONT_DEPTH").parse().unwrap();
    let source = nested_shader(&var("GFRONT_SHAPE"), depth);
    let ok = std::thread::Builder::new()
        .stack_size(stack)
        .spawn(move || {
            let mut log = InfoLog::default();
            let checked = compile_shader(&source, Stage::Fragment, &Options::default(), &mut log);
            let Some(checked) = checked else { return Err(log.text()) };
            let checked = std::sync::Arc::new(checked);
            let _ = super::link::recursive_functions(&checked);
            super::link::link(std::slice::from_ref(&checked), &[])?;
            super::lower::lower(&[&checked])?;
            Ok(())
        })
        .unwrap()
        .join()
        .unwrap();
    println!("result {ok:?}");
}

/// Times the phases of a shader of `GFRONT_FUNCTIONS` (100 000 unless set) one-line
/// functions, `main` calling the last (run by hand, `-- --ignored --nocapture`): every
/// phase should be linear in the number of functions.
#[test]
#[ignore]
fn many_functions_timing() {
    let n: usize = std::env::var("GFRONT_FUNCTIONS").map_or(100_000, |v| v.parse().unwrap());
    let mut src = String::from("#version 120\n");
    for i in 0..n {
        src.push_str(&format!("float f{i}(float x) {{ return x * {i}.0 + 1.0; }}\n"));
    }
    src.push_str(&format!("void main() {{ gl_FragColor = vec4(f{}(gl_Color.x)); }}\n", n - 1));
    let mut log = InfoLog::default();
    let start = std::time::Instant::now();
    let pre = super::preprocess::preprocess(&src, &Options::default(), &mut log);
    let t_pre = start.elapsed();
    let start = std::time::Instant::now();
    let tokens = super::lex::classify(&pre.tokens, pre.version, pre.end, &mut log);
    let t_lex = start.elapsed();
    let start = std::time::Instant::now();
    drop(super::parse::parse(&tokens, pre.version, &mut log).expect("parses"));
    let t_syntax = start.elapsed();
    drop((pre, tokens));
    println!("{n} functions: preprocess {t_pre:?}, tokens {t_lex:?}, parse {t_syntax:?}");
    let start = std::time::Instant::now();
    let parsed = parse_shader(&src, &Options::default(), &mut log).expect("parses");
    let t_parse = start.elapsed();
    let start = std::time::Instant::now();
    let checked = super::check::check(&parsed, Stage::Fragment, &super::Limits::default(), &mut log).expect("checks");
    let t_check = start.elapsed();
    let checked = std::sync::Arc::new(checked);
    let start = std::time::Instant::now();
    assert!(super::link::recursive_functions(&checked).is_empty());
    let t_recursion = start.elapsed();
    let start = std::time::Instant::now();
    super::link::link(std::slice::from_ref(&checked), &[]).expect("links");
    let t_link = start.elapsed();
    let start = std::time::Instant::now();
    super::lower::lower(&[&checked]).expect("lowers");
    let t_lower = start.elapsed();
    let start = std::time::Instant::now();
    drop((parsed, checked));
    let t_drop = start.elapsed();
    println!(
        "{n} functions: parse {t_parse:?}, check {t_check:?}, recursion {t_recursion:?}, link {t_link:?}, lower {t_lower:?}, free {t_drop:?}"
    );
}
