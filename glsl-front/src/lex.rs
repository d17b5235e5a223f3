//! The lexer, in two steps: source text → preprocessing tokens (identifiers, numbers,
//! punctuators, newlines) for the preprocessor, and its output → GLSL tokens (keywords of
//! the shader's version, reserved words, literals with their values, operators) for the
//! parser.
//!
//! Splitting it so means the preprocessor works on tokens, not text, and every token keeps
//! the position it had in the source, through macro expansion, to the parser's messages.
//! Line continuations (backslash-newline) are joined before tokenizing, in every version:
//! GLSL 1.10 and 1.20 do not name them, but Mesa joins them and piglit's 1.10 tests rely on
//! it. Comments become white space; a newline inside a block comment does not end a
//! directive (C's rule).

use super::diagnostics::{InfoLog, Pos};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PpKind {
    Ident,
    /// A preprocessing number: digits, letters, `.` and signed exponents, checked later.
    Number,
    Punct,
    /// A character that is no GLSL token (`"`, `$`, `@`, ...): an error only if the
    /// parser sees it (it may sit in a skipped section).
    Other,
    Newline,
}

/// A preprocessing token.
#[derive(Clone, Debug, PartialEq)]
pub struct PpToken {
    pub kind: PpKind,
    pub text: String,
    pub pos: Pos,
    /// White space (or a comment) before it on its line: `#define F(x)` against `#define F (x)`,
    /// and the same spelling when a macro is redefined.
    pub space_before: bool,
    /// Painted by macro expansion: the name of a macro that was being expanded when it
    /// appeared, never expanded again (C's rule, which forbids self-recursion).
    pub painted: bool,
}

/// The punctuators, longest first so that the first match is the longest.
const PUNCTUATORS: [&str; 48] = [
    "<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "^^", "*=", "/=", "+=", "-=", "%=", "&=",
    "^=", "|=", "##", "(", ")", "[", "]", "{", "}", ".", ",", ";", ":", "?", "+", "-", "*", "/", "%", "<", ">", "=",
    "!", "~", "&", "|", "^", "#", "\\",
];

/// The source's characters after line continuations are joined, each with its line and
/// column in the source.
fn join_continuations(source: &str) -> Vec<(u8, u32, u32)> {
    let bytes = source.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let (mut line, mut column) = (1u32, 1u32);
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        if b == b'\\' {
            // A backslash before a newline (\n, \r\n or \r) joins the lines.
            let next = bytes.get(i + 1).copied();
            let skip = match (next, bytes.get(i + 2).copied()) {
                (Some(b'\r'), Some(b'\n')) => 3,
                (Some(b'\n'), _) | (Some(b'\r'), _) => 2,
                _ => 0,
            };
            if skip > 0 {
                i += skip;
                line += 1;
                column = 1;
                continue;
            }
        }
        if b == b'\r' {
            // \r\n and a lone \r are newlines.
            if bytes.get(i + 1) == Some(&b'\n') {
                i += 1;
            }
            out.push((b'\n', line, column));
            line += 1;
            column = 1;
            i += 1;
            continue;
        }
        out.push((b, line, column));
        if b == b'\n' {
            line += 1;
            column = 1;
        } else if b & 0xC0 != 0x80 {
            column += 1; // one column per character, not per UTF-8 byte
        }
        i += 1;
    }
    out
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_char(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Splits a source string into preprocessing tokens, a `Newline` token ending each line
/// (and the last). An unterminated block comment is an error. Columns count white space
/// runs as one character, as Mesa's messages do (see [`renumber_columns`]).
pub fn tokenize(source: &str, source_number: u32, log: &mut InfoLog) -> Vec<PpToken> {
    let chars = join_continuations(source);
    let mut tokens = Vec::new();
    let mut i = 0;
    let mut space = false;
    // The column as Mesa counts it: in the text with each run of white space and comments
    // squeezed to one space (what its preprocessor hands its parser).
    let mut column = 1u32;
    let at = |i: usize| chars.get(i).map(|c| c.0);
    while i < chars.len() {
        let (b, line, _) = chars[i];
        let pos = Pos::new(source_number, line, column + space as u32);
        let push = |kind, text: String, tokens: &mut Vec<PpToken>, space: &mut bool, column: &mut u32| {
            *column = if kind == PpKind::Newline { 1 } else { pos.column + text.chars().count() as u32 };
            tokens.push(PpToken { kind, text, pos, space_before: *space, painted: false });
            *space = false;
        };
        match b {
            b'\n' => {
                push(PpKind::Newline, "\n".into(), &mut tokens, &mut space, &mut column);
                i += 1;
            }
            b' ' | b'\t' | 0x0B | 0x0C => {
                space = true;
                i += 1;
            }
            b'/' if at(i + 1) == Some(b'/') => {
                while i < chars.len() && chars[i].0 != b'\n' {
                    i += 1;
                }
                space = true;
            }
            b'/' if at(i + 1) == Some(b'*') => {
                i += 2;
                loop {
                    if i >= chars.len() {
                        log.preprocessor_error(pos, "Unterminated comment");
                        let line = chars.last().map_or(1, |c| c.1);
                        return tokens_with_final_newline(tokens, Pos::new(source_number, line, column + 1));
                    }
                    if chars[i].0 == b'*' && at(i + 1) == Some(b'/') {
                        i += 2;
                        break;
                    }
                    i += 1;
                }
                space = true;
            }
            _ if is_ident_start(b) => {
                let start = i;
                while i < chars.len() && is_ident_char(chars[i].0) {
                    i += 1;
                }
                let text = chars[start..i].iter().map(|c| c.0 as char).collect();
                push(PpKind::Ident, text, &mut tokens, &mut space, &mut column);
            }
            _ if b.is_ascii_digit() || (b == b'.' && at(i + 1).is_some_and(|c| c.is_ascii_digit())) => {
                let start = i;
                i += 1;
                while let Some(c) = at(i) {
                    // A sign belongs to the number after the exponent's `e` (not in hex).
                    let exponent_sign = (c == b'+' || c == b'-')
                        && matches!(chars[i - 1].0, b'e' | b'E')
                        && !is_hex_number(&chars[start..i]);
                    if !(exponent_sign || is_ident_char(c) || c == b'.') {
                        break;
                    }
                    i += 1;
                }
                let text = chars[start..i].iter().map(|c| c.0 as char).collect();
                push(PpKind::Number, text, &mut tokens, &mut space, &mut column);
            }
            _ => {
                let matches = |p: &&&str| {
                    let n = p.len();
                    i + n <= chars.len() && chars[i..i + n].iter().map(|c| c.0).eq(p.bytes())
                };
                if let Some(p) = PUNCTUATORS.iter().find(matches) {
                    i += p.len();
                    push(PpKind::Punct, (*p).to_string(), &mut tokens, &mut space, &mut column);
                } else {
                    // One character, whole (UTF-8 continuation bytes with it).
                    let start = i;
                    i += 1;
                    while i < chars.len() && chars[i].0 & 0xC0 == 0x80 {
                        i += 1;
                    }
                    let bytes: Vec<u8> = chars[start..i].iter().map(|c| c.0).collect();
                    push(
                        PpKind::Other,
                        String::from_utf8_lossy(&bytes).into_owned(),
                        &mut tokens,
                        &mut space,
                        &mut column,
                    );
                }
            }
        }
    }
    let line = chars.last().map_or(1, |c| c.1);
    tokens_with_final_newline(tokens, Pos::new(source_number, line, column + space as u32))
}

fn is_hex_number(chars: &[(u8, u32, u32)]) -> bool {
    chars.len() >= 2 && chars[0].0 == b'0' && matches!(chars[1].0, b'x' | b'X')
}

fn tokens_with_final_newline(mut tokens: Vec<PpToken>, end: Pos) -> Vec<PpToken> {
    if tokens.last().is_none_or(|t| t.kind != PpKind::Newline) {
        tokens.push(PpToken {
            kind: PpKind::Newline,
            text: "\n".into(),
            pos: end,
            space_before: false,
            painted: false,
        });
    }
    tokens
}

/// The keywords of GLSL 1.10 and 1.20 (1.20's only where the shader says `#version 120`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Keyword {
    Attribute,
    Const,
    Uniform,
    Varying,
    Centroid,
    Invariant,
    Break,
    Continue,
    Do,
    For,
    While,
    If,
    Else,
    In,
    Out,
    Inout,
    Void,
    Float,
    Int,
    Bool,
    True,
    False,
    Discard,
    Return,
    Struct,
    /// `vec2`..`vec4` (n), `ivec`, `bvec`.
    Vec(u8),
    IVec(u8),
    BVec(u8),
    /// `matC` and `matCxR`: columns, rows.
    Mat(u8, u8),
    Sampler(Sampler),
}

/// The sampler types of GLSL 1.10 and 1.20.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sampler {
    S1D,
    S2D,
    S3D,
    Cube,
    S1DShadow,
    S2DShadow,
}

impl Sampler {
    pub fn name(self) -> &'static str {
        match self {
            Sampler::S1D => "sampler1D",
            Sampler::S2D => "sampler2D",
            Sampler::S3D => "sampler3D",
            Sampler::Cube => "samplerCube",
            Sampler::S1DShadow => "sampler1DShadow",
            Sampler::S2DShadow => "sampler2DShadow",
        }
    }
}

/// The keyword `word` is in GLSL `version`, if it is one.
pub fn keyword(word: &str, version: u32) -> Option<Keyword> {
    use Keyword::*;
    let v120 = version >= 120;
    Some(match word {
        "attribute" => Attribute,
        "const" => Const,
        "uniform" => Uniform,
        "varying" => Varying,
        "centroid" if v120 => Centroid,
        "invariant" if v120 => Invariant,
        "break" => Break,
        "continue" => Continue,
        "do" => Do,
        "for" => For,
        "while" => While,
        "if" => If,
        "else" => Else,
        "in" => In,
        "out" => Out,
        "inout" => Inout,
        "void" => Void,
        "float" => Float,
        "int" => Int,
        "bool" => Bool,
        "true" => True,
        "false" => False,
        "discard" => Discard,
        "return" => Return,
        "struct" => Struct,
        "vec2" => Vec(2),
        "vec3" => Vec(3),
        "vec4" => Vec(4),
        "ivec2" => IVec(2),
        "ivec3" => IVec(3),
        "ivec4" => IVec(4),
        "bvec2" => BVec(2),
        "bvec3" => BVec(3),
        "bvec4" => BVec(4),
        "mat2" => Mat(2, 2),
        "mat3" => Mat(3, 3),
        "mat4" => Mat(4, 4),
        "sampler1D" => Sampler(self::Sampler::S1D),
        "sampler2D" => Sampler(self::Sampler::S2D),
        "sampler3D" => Sampler(self::Sampler::S3D),
        "samplerCube" => Sampler(self::Sampler::Cube),
        "sampler1DShadow" => Sampler(self::Sampler::S1DShadow),
        "sampler2DShadow" => Sampler(self::Sampler::S2DShadow),
        _ if v120 => {
            // matCxR, C and R in 2..4.
            let b = word.as_bytes();
            if b.len() == 6 && word.starts_with("mat") && b[4] == b'x' {
                let (c, r) = (b[3].wrapping_sub(b'0'), b[5].wrapping_sub(b'0'));
                if (2..=4).contains(&c) && (2..=4).contains(&r) {
                    return Some(Mat(c, r));
                }
            }
            return None;
        }
        _ => return None,
    })
}

/// The words GLSL `version` reserves for future use: using one is an error.
pub fn is_reserved(word: &str, version: u32) -> bool {
    const RESERVED: [&str; 38] = [
        "asm",
        "class",
        "union",
        "enum",
        "typedef",
        "template",
        "this",
        "packed",
        "goto",
        "switch",
        "default",
        "inline",
        "noinline",
        "volatile",
        "public",
        "static",
        "extern",
        "external",
        "interface",
        "long",
        "short",
        "double",
        "half",
        "fixed",
        "unsigned",
        "input",
        "output",
        "hvec2",
        "hvec3",
        "hvec4",
        "dvec2",
        "dvec3",
        "dvec4",
        "fvec2",
        "fvec3",
        "fvec4",
        "sizeof",
        "cast",
    ];
    const RESERVED_TOO: [&str; 5] = ["namespace", "using", "sampler2DRect", "sampler3DRect", "sampler2DRectShadow"];
    // GLSL 1.20 (section 3.6) adds the precision words of OpenGL ES to the list.
    const RESERVED_120: [&str; 4] = ["lowp", "mediump", "highp", "precision"];
    RESERVED.contains(&word) || RESERVED_TOO.contains(&word) || (version >= 120 && RESERVED_120.contains(&word))
}

/// A GLSL token.
#[derive(Clone, Debug, PartialEq)]
pub enum TokenKind {
    Ident(String),
    Keyword(Keyword),
    /// An integer literal's 32 bits (a value above `i32::MAX` wraps, as in Mesa).
    Int(u32),
    Float(f32),
    Punct(&'static str),
    /// Something the lexer refused (a reserved word, a bad literal, a stray character),
    /// with the message the parser reports when it reaches it.
    Invalid(String),
    End,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    pub kind: TokenKind,
    pub pos: Pos,
}

/// The preprocessor's output as GLSL tokens for `version`, ending with [`TokenKind::End`]
/// at `end`.
pub fn classify(tokens: &[PpToken], version: u32, end: Pos, log: &mut InfoLog) -> Vec<Token> {
    let mut out = Vec::with_capacity(tokens.len() + 1);
    for t in tokens {
        let kind = match t.kind {
            PpKind::Newline => continue,
            PpKind::Ident => {
                if let Some(k) = keyword(&t.text, version) {
                    TokenKind::Keyword(k)
                } else if is_reserved(&t.text, version) {
                    TokenKind::Invalid(format!("illegal use of reserved word `{}'", t.text))
                } else {
                    TokenKind::Ident(t.text.clone())
                }
            }
            PpKind::Number => {
                if let Some(w) = number_warning(&t.text, version) {
                    log.warning(t.pos, w);
                }
                number(&t.text, version)
            }
            PpKind::Punct => match PUNCTUATORS.iter().find(|p| **p == t.text) {
                Some(&p) if p != "#" && p != "##" && p != "\\" => TokenKind::Punct(p),
                _ => TokenKind::Invalid(format!("syntax error, unexpected `{}'", t.text)),
            },
            PpKind::Other => TokenKind::Invalid(format!("syntax error, unexpected character `{}'", t.text)),
        };
        out.push(Token { kind, pos: t.pos });
    }
    out.push(Token { kind: TokenKind::End, pos: end });
    out
}

/// The columns of the preprocessor's output as Mesa reports them: on each output line,
/// tokens one space apart where white space separated them (in the source or in a macro's
/// body), so that a message about an expanded macro points where Mesa's does.
pub fn renumber_columns(tokens: &mut [PpToken]) {
    let mut line = (u32::MAX, u32::MAX);
    let mut column = 1u32;
    for t in tokens {
        if (t.pos.source, t.pos.line) != line {
            line = (t.pos.source, t.pos.line);
            column = 1;
        }
        column += t.space_before as u32;
        t.pos.column = column;
        column += t.text.chars().count() as u32;
    }
}

/// The value of a numeric literal, or why it is none.
pub fn number(text: &str, version: u32) -> TokenKind {
    let b = text.as_bytes();
    let hex = is_hex_text(text);
    let float_like = !hex && (text.contains('.') || text.contains(['e', 'E']) || text.ends_with(['f', 'F']));
    if float_like {
        return float_literal(text, version);
    }
    let (digits, radix) = if hex {
        (&text[2..], 16)
    } else if b.len() > 1 && b[0] == b'0' {
        (&text[1..], 8)
    } else {
        (text, 10)
    };
    let kind = match radix {
        16 => "hexadecimal",
        8 => "octal",
        _ => "decimal",
    };
    if digits.is_empty() && radix == 16 || !digits.chars().all(|c| c.is_digit(radix)) {
        return TokenKind::Invalid(format!("invalid {kind} integer literal `{text}'"));
    }
    TokenKind::Int(integer_value(digits, radix) as u32)
}

/// An integer's value, saturating at `u64::MAX` (as C's `strtoull`).
fn integer_value(digits: &str, radix: u32) -> u64 {
    digits.chars().fold(0u64, |v, c| {
        v.checked_mul(radix as u64)
            .and_then(|v| v.checked_add(c.to_digit(radix).unwrap_or(0) as u64))
            .unwrap_or(u64::MAX)
    })
}

/// What Mesa warns about in a literal that it accepts: an integer above 32 bits (its low
/// 32 bits are kept) and, in GLSL 1.10, a float's `f` suffix (1.20's; the 1.10 grammar has
/// none, but Mesa compiles it, and so do the shaders written against Mesa).
pub fn number_warning(text: &str, version: u32) -> Option<String> {
    match number(text, version) {
        TokenKind::Int(_) => {
            let (digits, radix) = if is_hex_text(text) {
                (&text[2..], 16)
            } else if text.len() > 1 && text.starts_with('0') {
                (&text[1..], 8)
            } else {
                (text, 10)
            };
            (integer_value(digits, radix) > u32::MAX as u64).then(|| format!("literal value `{text}' out of range"))
        }
        TokenKind::Float(_) if version < 120 && text.ends_with(['f', 'F']) => {
            Some(format!("floating-point suffix in `{text}' is not valid in GLSL 1.10"))
        }
        _ => None,
    }
}

fn is_hex_text(text: &str) -> bool {
    text.len() >= 2 && text.as_bytes()[0] == b'0' && matches!(text.as_bytes()[1], b'x' | b'X')
}

/// A float literal: digits with a point and/or an exponent, and an optional `f`/`F` suffix
/// (GLSL 1.20's section 4.1.4; in 1.10 see [`number_warning`]).
fn float_literal(text: &str, version: u32) -> TokenKind {
    let invalid = || TokenKind::Invalid(format!("invalid floating-point literal `{text}'"));
    let mut body = text;
    if let Some(stripped) = text.strip_suffix(['f', 'F']) {
        let _ = version; // accepted in 1.10 with a warning (number_warning)
        body = stripped;
    }
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    let (int_part, frac_part) = match mantissa.find('.') {
        Some(i) => (&mantissa[..i], Some(&mantissa[i + 1..])),
        None => (mantissa, None),
    };
    let digits = |s: &str| s.bytes().all(|c| c.is_ascii_digit());
    let frac_ok = frac_part.is_none_or(digits);
    let has_digits = !int_part.is_empty() || frac_part.is_some_and(|f| !f.is_empty());
    let exp_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        !e.is_empty() && digits(e)
    });
    if !digits(int_part) || !frac_ok || !has_digits || !exp_ok || (frac_part.is_none() && exponent.is_none()) {
        return invalid();
    }
    // Rust's parser rounds correctly to nearest; overflow gives infinity, as Mesa's strtof.
    match body.parse::<f32>() {
        Ok(v) => TokenKind::Float(v),
        Err(_) => invalid(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(src: &str) -> Vec<String> {
        let mut log = InfoLog::default();
        tokenize(src, 0, &mut log).into_iter().map(|t| t.text).collect()
    }

    #[test]
    fn tokens_split_with_longest_punctuators_and_comments_as_space() {
        assert_eq!(texts("a<<=b/*x\ny*/c//d\n1.5e-3"), ["a", "<<=", "b", "c", "\n", "1.5e-3", "\n"]);
        assert_eq!(texts("x+++y"), ["x", "++", "+", "y", "\n"]);
        assert_eq!(texts("0x1e+1"), ["0x1e", "+", "1", "\n"]);
    }

    #[test]
    fn continuations_join_lines_and_positions_stay_in_the_source() {
        let mut log = InfoLog::default();
        let t = tokenize("ab\\\ncd ef\n  g\t /* x */  h", 0, &mut log);
        assert_eq!(t[0].text, "abcd");
        assert_eq!((t[1].text.as_str(), t[1].pos.line, t[1].pos.column), ("ef", 2, 6));
        // Columns count a run of white space and comments as one character (Mesa's count).
        assert_eq!((t[3].text.as_str(), t[3].pos.line, t[3].pos.column), ("g", 3, 2));
        assert_eq!((t[4].text.as_str(), t[4].pos.column), ("h", 4));
    }

    #[test]
    fn an_unterminated_comment_is_an_error() {
        let mut log = InfoLog::default();
        tokenize("a /* b", 0, &mut log);
        assert_eq!(log.text(), "0:1(3): preprocessor error: Unterminated comment\n");
    }

    #[test]
    fn literals_have_their_values_and_bad_ones_are_refused() {
        assert_eq!(number("017", 110), TokenKind::Int(15));
        assert_eq!(number("0x1F", 110), TokenKind::Int(31));
        assert_eq!(number("4294967295", 110), TokenKind::Int(u32::MAX));
        assert_eq!(number_warning("4294967295", 110), None);
        // Mesa keeps the low 32 bits and warns.
        assert_eq!(number("4294967297", 110), TokenKind::Int(1));
        assert!(number_warning("4294967297", 110).is_some_and(|m| m.contains("out of range")));
        assert_eq!(number("99999999999999999999999", 110), TokenKind::Int(u32::MAX));
        assert!(matches!(number("08", 110), TokenKind::Invalid(_)));
        assert!(matches!(number("0xg", 110), TokenKind::Invalid(_)));
        assert!(matches!(number("0x", 110), TokenKind::Invalid(_)));
        assert_eq!(number("1.5e2", 110), TokenKind::Float(150.0));
        assert_eq!(number(".5", 110), TokenKind::Float(0.5));
        assert_eq!(number("2.", 110), TokenKind::Float(2.0));
        assert_eq!(number("1E-1", 110), TokenKind::Float(0.1));
        assert_eq!(number("1e5f", 120), TokenKind::Float(1e5));
        assert_eq!(number("1.0F", 120), TokenKind::Float(1.0));
        assert_eq!(number("1.0f", 110), TokenKind::Float(1.0));
        assert!(number_warning("1.0f", 110).is_some_and(|m| m.contains("GLSL 1.10")));
        assert_eq!(number_warning("1.0f", 120), None);
        assert!(matches!(number("1e", 110), TokenKind::Invalid(_)));
        assert!(matches!(number("1.0.0", 110), TokenKind::Invalid(_)));
        assert!(matches!(number("1u", 120), TokenKind::Invalid(_)));
    }

    #[test]
    fn keywords_follow_the_version() {
        assert_eq!(keyword("invariant", 110), None);
        assert_eq!(keyword("invariant", 120), Some(Keyword::Invariant));
        assert_eq!(keyword("mat2x3", 110), None);
        assert_eq!(keyword("mat2x3", 120), Some(Keyword::Mat(2, 3)));
        assert_eq!(keyword("mat4x4", 120), Some(Keyword::Mat(4, 4)));
        assert_eq!(keyword("mat5x4", 120), None);
        assert!(is_reserved("goto", 110) && is_reserved("sampler2DRect", 120));
        assert!(!is_reserved("precision", 110) && is_reserved("precision", 120));
        assert!(!is_reserved("gotos", 120));
    }
}
