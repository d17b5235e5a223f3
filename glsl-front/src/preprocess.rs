//! The GLSL 1.10/1.20 preprocessor: directives, conditional compilation and macro
//! expansion over the lexer's preprocessing tokens, as chapter 3.3 of the specifications
//! describes it (C's preprocessor without strings, `#include` or stringification).
//!
//! It works line by line: a line whose first token is `#` is a directive, other lines of
//! the sections being compiled gather until the next directive and are then expanded
//! together (so a function-like macro's arguments may span lines). Expansion follows C:
//! arguments are expanded before substitution (not beside `##`), the result is rescanned
//! with the rest of the text, and a macro's own name inside its expansion is painted and
//! never expanded again. Limits keep pathological input bounded: the expanded text of a
//! compile and the nesting of macro arguments have ceilings, past which it is an error.
//!
//! Where GLSL differs from C: `#line N` makes the *next* line N + 1 (GLSL 1.10/1.20 section 3.3; C and GLSL 3.30 make
//! it N); `#version` and `#extension` lines are not macro-expanded; macro names starting
//! with `GL_` are reserved (an error), names containing `__` draw a warning as in Mesa
//! (both specifications reserve them; piglit's 1.10 tests require such identifiers to
//! compile). Identifiers in `#if` that are no macro count 0, as in C and in Mesa, though
//! the GLSL specifications make them an error: tessera compiles what Mesa compiles.

use super::diagnostics::{InfoLog, Pos};
use super::lex::{self, PpKind, PpToken, TokenKind};
use std::collections::{HashMap, VecDeque};

/// The GLSL versions this front end compiles.
pub const SUPPORTED_VERSIONS: [u32; 2] = [110, 120];

/// Ceiling on the tokens macro expansion may produce in one compile (a macro that doubles
/// its text ten levels deep would otherwise take the memory of the process).
const EXPANSION_BUDGET: usize = 1 << 22;
/// Ceiling on macro invocations nested in macro arguments.
const MAX_ARGUMENT_DEPTH: usize = 64;

/// What the driver supports, as far as the preprocessor needs to know.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Extensions a shader may enable; each is also defined as a macro of value 1.
    pub extensions: Vec<String>,
}

/// An `#extension` directive's behaviour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Behavior {
    Require,
    Enable,
    Warn,
    Disable,
}

/// An `#extension` directive, recorded for semantic analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct Extension {
    pub name: String,
    pub behavior: Behavior,
    pub pos: Pos,
}

/// The preprocessor's result.
#[derive(Clone, Debug)]
pub struct Preprocessed {
    /// The shader's GLSL version: `#version`'s, or 110 without one.
    pub version: u32,
    /// The text to compile: the tokens of the compiled sections after expansion.
    pub tokens: Vec<PpToken>,
    pub extensions: Vec<Extension>,
    /// `#pragma STDGL invariant(all)` was seen (GLSL 1.20 section 4.6.1).
    pub invariant_all: bool,
    /// Where the text ends (for messages about an unexpected end).
    pub end: Pos,
}

#[derive(Clone, Debug)]
struct Macro {
    /// The parameters of a function-like macro; `None` for an object-like one.
    params: Option<Vec<String>>,
    body: Vec<PpToken>,
    /// Predefined: cannot be redefined or undefined.
    builtin: bool,
}

/// One open `#if` group.
struct Cond {
    /// The enclosing sections are compiled.
    parent_active: bool,
    /// This group's current section is compiled.
    active: bool,
    /// Some section of the group was (so later `#elif`/`#else` sections are not).
    taken: bool,
    seen_else: bool,
    pos: Pos,
}

/// An item of the expansion queue: a token, or the end of the macro expansion begun last.
enum Item {
    Tok(PpToken),
    Pop,
}

struct Pp<'a> {
    log: &'a mut InfoLog,
    options: &'a Options,
    macros: HashMap<String, Macro>,
    conds: Vec<Cond>,
    out: Vec<PpToken>,
    pending: Vec<PpToken>,
    version: u32,
    /// Anything (a token or a directive) was seen: `#version` must come first.
    seen_anything: bool,
    /// `#line`'s effect: reported line = source line + `line_delta`.
    line_delta: i64,
    source: u32,
    extensions: Vec<Extension>,
    invariant_all: bool,
    expanded: usize,
    /// The budget ran out: the error is reported once and expansion stops.
    exhausted: bool,
}

/// Runs the preprocessor over one shader source.
pub fn preprocess(source: &str, options: &Options, log: &mut InfoLog) -> Preprocessed {
    let tokens = lex::tokenize(source, 0, log);
    let mut pp = Pp {
        log,
        options,
        macros: HashMap::new(),
        conds: Vec::new(),
        out: Vec::new(),
        pending: Vec::new(),
        version: 110,
        seen_anything: false,
        line_delta: 0,
        source: 0,
        extensions: Vec::new(),
        invariant_all: false,
        expanded: 0,
        exhausted: false,
    };
    for name in &options.extensions {
        pp.define_builtin(name, "1");
    }
    let mut end = Pos::new(0, 1, 1);
    let mut line = Vec::new();
    for mut t in tokens {
        t.pos.line = (t.pos.line as i64 + pp.line_delta).clamp(0, u32::MAX as i64) as u32;
        t.pos.source = pp.source;
        if t.kind == PpKind::Newline {
            end = t.pos;
            pp.line(std::mem::take(&mut line), t.pos);
        } else {
            line.push(t);
        }
    }
    pp.flush();
    for c in std::mem::take(&mut pp.conds) {
        pp.log.preprocessor_error(c.pos, "Unterminated #if");
    }
    lex::renumber_columns(&mut pp.out);
    Preprocessed {
        version: pp.version,
        tokens: pp.out,
        extensions: pp.extensions,
        invariant_all: pp.invariant_all,
        end,
    }
}

fn is_punct(t: Option<&PpToken>, p: &str) -> bool {
    t.is_some_and(|t| t.kind == PpKind::Punct && t.text == p)
}

fn number_token(text: String, like: &PpToken) -> PpToken {
    PpToken { kind: PpKind::Number, text, pos: like.pos, space_before: like.space_before, painted: false }
}

/// The tokens' text with their spacing (for `#error` and messages).
fn spell(tokens: &[PpToken]) -> String {
    let mut s = String::new();
    for (i, t) in tokens.iter().enumerate() {
        if i > 0 && t.space_before {
            s.push(' ');
        }
        s.push_str(&t.text);
    }
    s
}

impl Pp<'_> {
    fn active(&self) -> bool {
        self.conds.last().is_none_or(|c| c.active)
    }

    fn define_builtin(&mut self, name: &str, value: &str) {
        let body = vec![PpToken {
            kind: PpKind::Number,
            text: value.into(),
            pos: Pos::default(),
            space_before: false,
            painted: false,
        }];
        self.macros.insert(name.into(), Macro { params: None, body, builtin: true });
    }

    /// One line of the source; `end` is where it ends (Mesa reports `#if` errors there).
    fn line(&mut self, line: Vec<PpToken>, end: Pos) {
        if line.is_empty() {
            return;
        }
        if is_punct(line.first(), "#") {
            self.flush();
            self.directive(&line, end);
            self.seen_anything = true;
        } else {
            self.seen_anything = true;
            if self.active() {
                self.pending.extend(line);
            }
        }
    }

    /// Expands the gathered text into the output.
    fn flush(&mut self) {
        if self.pending.is_empty() {
            return;
        }
        let text = std::mem::take(&mut self.pending);
        let expanded = self.expand(text, &mut Vec::new(), 0);
        self.out.extend(expanded);
    }

    fn directive(&mut self, line: &[PpToken], end: Pos) {
        let hash = &line[0];
        let Some(name) = line.get(1) else { return }; // the null directive
        let rest = &line[2..];
        let active = self.active();
        if name.kind != PpKind::Ident {
            if active {
                self.log.preprocessor_error(hash.pos, format!("invalid directive `#{}'", name.text));
            }
            return;
        }
        match name.text.as_str() {
            "if" | "ifdef" | "ifndef" => {
                let value = if !active {
                    false
                } else if name.text == "if" {
                    self.condition(rest, end)
                } else {
                    match rest.first() {
                        Some(t) if t.kind == PpKind::Ident => {
                            if rest.len() > 1 {
                                self.log
                                    .preprocessor_warning(rest[1].pos, format!("extra tokens after #{}", name.text));
                            }
                            self.macros.contains_key(&t.text) == (name.text == "ifdef")
                        }
                        _ => {
                            self.log.preprocessor_error(hash.pos, format!("#{} needs a macro name", name.text));
                            false
                        }
                    }
                };
                self.conds.push(Cond {
                    parent_active: active,
                    active: value,
                    taken: value,
                    seen_else: false,
                    pos: end,
                });
            }
            "elif" => {
                let Some(c) = self.conds.last() else {
                    self.log.preprocessor_error(hash.pos, "#elif without #if");
                    return;
                };
                if c.seen_else {
                    self.log.preprocessor_error(hash.pos, "#elif after #else");
                    return;
                }
                // A group already taken does not evaluate its later expressions (C's rule).
                let value = if c.parent_active && !c.taken { self.condition(rest, end) } else { false };
                let c = self.conds.last_mut().expect("checked above");
                c.active = value;
                c.taken |= value;
            }
            "else" => {
                let Some(c) = self.conds.last_mut() else {
                    self.log.preprocessor_error(hash.pos, "#else without #if");
                    return;
                };
                if c.seen_else {
                    self.log.preprocessor_error(hash.pos, "#else after #else");
                    return;
                }
                c.seen_else = true;
                c.active = c.parent_active && !c.taken;
                c.taken = true;
            }
            "endif" => {
                if self.conds.pop().is_none() {
                    self.log.preprocessor_error(hash.pos, "#endif without #if");
                }
            }
            _ if !active => {} // other directives of skipped sections are not looked at
            "define" => self.define(rest, hash.pos),
            "undef" => self.undef(rest, hash.pos),
            "line" => self.line_directive(rest, hash.pos),
            "error" => {
                let text = spell(rest);
                self.log.preprocessor_error(hash.pos, format!("#error {text}").trim_end().to_string());
            }
            "pragma" => {
                let text = spell(rest);
                if text.replace(' ', "") == "STDGLinvariant(all)" {
                    self.invariant_all = true;
                }
            }
            "extension" => self.extension(rest, hash.pos),
            "version" => self.version(rest, hash.pos),
            other => self.log.preprocessor_error(hash.pos, format!("invalid directive `#{other}'")),
        }
    }

    fn version(&mut self, rest: &[PpToken], pos: Pos) {
        if self.seen_anything {
            self.log.error(pos, "#version must be the first directive of the shader");
            return;
        }
        let Some(number) = rest.first().filter(|t| t.kind == PpKind::Number) else {
            self.log.error(pos, "#version needs a version number");
            return;
        };
        let value = match lex::number(&number.text, 110) {
            TokenKind::Int(v) if lex::number_warning(&number.text, 110).is_none() => v,
            _ => {
                self.log.error(number.pos, format!("invalid version number `{}'", number.text));
                return;
            }
        };
        let profile = rest.get(1).map(|t| t.text.as_str());
        let es = value == 100 || profile == Some("es");
        let name = format!("GLSL {}{}.{:02}", if es { "ES " } else { "" }, value / 100, value % 100);
        if es || !SUPPORTED_VERSIONS.contains(&value) {
            self.log.error(pos, format!("{name} is not supported. Supported versions are: 1.10 and 1.20"));
            return;
        }
        if let Some(p) = rest.get(1) {
            self.log.error(p.pos, format!("versions before 1.50 take no profile (`{}')", p.text));
            return;
        }
        self.version = value;
    }

    fn extension(&mut self, rest: &[PpToken], pos: Pos) {
        let shape_ok = rest.len() == 3
            && rest[0].kind == PpKind::Ident
            && is_punct(rest.get(1), ":")
            && rest[2].kind == PpKind::Ident;
        if !shape_ok {
            self.log.error(pos, "syntax error in #extension: expected `#extension name : behavior'");
            return;
        }
        let (name, word) = (&rest[0].text, &rest[2].text);
        let behavior = match word.as_str() {
            "require" => Behavior::Require,
            "enable" => Behavior::Enable,
            "warn" => Behavior::Warn,
            "disable" => Behavior::Disable,
            _ => {
                self.log.error(rest[2].pos, format!("unknown extension behavior `{word}'"));
                return;
            }
        };
        if name == "all" {
            if matches!(behavior, Behavior::Require | Behavior::Enable) {
                self.log.error(pos, format!("behavior `{word}' is not allowed with `all'"));
                return;
            }
        } else if !self.options.extensions.contains(name) {
            match behavior {
                Behavior::Require => {
                    self.log.error(rest[0].pos, format!("extension `{name}' unsupported"));
                    return;
                }
                Behavior::Enable | Behavior::Warn => {
                    self.log.warning(rest[0].pos, format!("extension `{name}' unsupported"))
                }
                Behavior::Disable => {}
            }
        }
        self.extensions.push(Extension { name: name.clone(), behavior, pos });
    }

    fn line_directive(&mut self, rest: &[PpToken], pos: Pos) {
        let expanded = self.expand(rest.to_vec(), &mut Vec::new(), 0);
        let values: Vec<Option<u32>> = expanded
            .iter()
            .map(|t| match (t.kind, lex::number(&t.text, self.version)) {
                (PpKind::Number, TokenKind::Int(v)) => Some(v),
                _ => None,
            })
            .collect();
        let (line, source) = match values.as_slice() {
            [Some(l)] => (*l, None),
            [Some(l), Some(s)] => (*l, Some(*s)),
            _ => {
                self.log.preprocessor_error(pos, "#line needs a line number and an optional source string number");
                return;
            }
        };
        // The directive's own line is pos.line; the next is line + 1 (GLSL 1.10/1.20).
        let physical_next = pos.line as i64 - self.line_delta + 1;
        self.line_delta = line as i64 + 1 - physical_next;
        if let Some(s) = source {
            self.source = s;
        }
    }

    fn check_name(&mut self, t: &PpToken, undef: bool) -> bool {
        if self.macros.get(&t.text).is_some_and(|m| m.builtin)
            || ["__LINE__", "__FILE__", "__VERSION__"].contains(&t.text.as_str())
        {
            let what = if undef { "undefined" } else { "redefined" };
            self.log.preprocessor_error(t.pos, format!("predefined macro `{}' cannot be {what}", t.text));
            return false;
        }
        if t.text.starts_with("GL_") {
            self.log.preprocessor_error(t.pos, format!("macro names starting with `GL_' are reserved (`{}')", t.text));
            return false;
        }
        if t.text == "defined" {
            self.log.preprocessor_error(t.pos, "`defined' cannot be a macro name");
            return false;
        }
        if t.text.contains("__") && !undef {
            self.log.preprocessor_warning(
                t.pos,
                format!("macro names containing `__' are reserved for the implementation (`{}')", t.text),
            );
        }
        true
    }

    fn define(&mut self, rest: &[PpToken], pos: Pos) {
        let Some(name) = rest.first().filter(|t| t.kind == PpKind::Ident) else {
            self.log.preprocessor_error(pos, "#define needs a macro name");
            return;
        };
        if !self.check_name(name, false) {
            return;
        }
        let mut i = 1;
        let params = if is_punct(rest.get(1), "(") && !rest[1].space_before {
            let mut params: Vec<String> = Vec::new();
            i = 2;
            if is_punct(rest.get(i), ")") {
                i += 1;
            } else {
                loop {
                    match rest.get(i) {
                        Some(p) if p.kind == PpKind::Ident => {
                            if params.contains(&p.text) {
                                self.log.preprocessor_error(p.pos, format!("duplicate macro parameter `{}'", p.text));
                                return;
                            }
                            params.push(p.text.clone());
                        }
                        other => {
                            let at = other.map_or(pos, |t| t.pos);
                            self.log.preprocessor_error(
                                at,
                                format!("bad parameter list in the definition of `{}'", name.text),
                            );
                            return;
                        }
                    }
                    i += 1;
                    if is_punct(rest.get(i), ",") {
                        i += 1;
                    } else if is_punct(rest.get(i), ")") {
                        i += 1;
                        break;
                    } else {
                        let at = rest.get(i).map_or(pos, |t| t.pos);
                        self.log
                            .preprocessor_error(at, format!("bad parameter list in the definition of `{}'", name.text));
                        return;
                    }
                }
            }
            Some(params)
        } else {
            None
        };
        let mut body = rest[i..].to_vec();
        if let Some(first) = body.first_mut() {
            first.space_before = false;
        }
        if let Some(t) = body.iter().find(|t| t.kind == PpKind::Punct && t.text == "#") {
            self.log.preprocessor_error(t.pos, "`#' is not valid in a macro body (GLSL has no stringification)");
            return;
        }
        if is_punct(body.first(), "##") || is_punct(body.last(), "##") {
            self.log.preprocessor_error(pos, "`##' cannot begin or end a macro body");
            return;
        }
        if let Some(old) = self.macros.get(&name.text) {
            let same_body = old.body.len() == body.len()
                && old.body.iter().zip(&body).all(|(a, b)| a.text == b.text && a.space_before == b.space_before);
            if old.params != params || !same_body {
                self.log.preprocessor_error(name.pos, format!("Redefinition of macro `{}'", name.text));
                return;
            }
        }
        self.macros.insert(name.text.clone(), Macro { params, body, builtin: false });
    }

    fn undef(&mut self, rest: &[PpToken], pos: Pos) {
        let Some(name) = rest.first().filter(|t| t.kind == PpKind::Ident) else {
            self.log.preprocessor_error(pos, "#undef needs a macro name");
            return;
        };
        if self.check_name(name, true) {
            self.macros.remove(&name.text);
        }
    }

    /// Evaluates an `#if`/`#elif` expression (an error counts as false).
    fn condition(&mut self, rest: &[PpToken], pos: Pos) -> bool {
        // `defined X` and `defined(X)` first, before their operands could expand.
        let mut replaced = Vec::with_capacity(rest.len());
        let mut i = 0;
        while i < rest.len() {
            let t = &rest[i];
            if t.kind == PpKind::Ident && t.text == "defined" {
                let (name, next) = if is_punct(rest.get(i + 1), "(") {
                    if !is_punct(rest.get(i + 3), ")") {
                        (None, i + 1)
                    } else {
                        (rest.get(i + 2), i + 4)
                    }
                } else {
                    (rest.get(i + 1), i + 2)
                };
                let Some(name) = name.filter(|n| n.kind == PpKind::Ident) else {
                    self.log.preprocessor_error(t.pos, "`defined' needs a macro name");
                    return false;
                };
                let value = self.macros.contains_key(&name.text)
                    || ["__LINE__", "__FILE__", "__VERSION__"].contains(&name.text.as_str());
                replaced.push(number_token(if value { "1" } else { "0" }.into(), t));
                i = next;
            } else {
                replaced.push(t.clone());
                i += 1;
            }
        }
        let tokens = self.expand(replaced, &mut Vec::new(), 0);
        if tokens.is_empty() {
            self.log.preprocessor_error(pos, "#if with no expression");
            return false;
        }
        let mut eval = Eval { tokens: &tokens, at: 0, log: self.log, version: self.version, pos };
        match eval.expr(0) {
            Ok(v) if eval.at == tokens.len() => v != 0,
            Ok(_) => {
                let t = &tokens[eval.at];
                self.log.preprocessor_error(pos, format!("syntax error in #if: unexpected `{}'", t.text));
                false
            }
            Err(()) => false,
        }
    }

    /// Expands the macros of `input`; `active` holds the macros being expanded around it.
    fn expand(&mut self, input: Vec<PpToken>, active: &mut Vec<String>, depth: usize) -> Vec<PpToken> {
        let mut queue: VecDeque<Item> = input.into_iter().map(Item::Tok).collect();
        let mut out = Vec::new();
        let base = active.len();
        while let Some(item) = queue.pop_front() {
            let mut t = match item {
                Item::Pop => {
                    active.pop();
                    continue;
                }
                Item::Tok(t) => t,
            };
            if t.kind != PpKind::Ident || t.painted || self.exhausted {
                out.push(t);
                continue;
            }
            if active.contains(&t.text) {
                t.painted = true;
                out.push(t);
                continue;
            }
            let dynamic = match t.text.as_str() {
                "__LINE__" => Some(t.pos.line.to_string()),
                "__FILE__" => Some(t.pos.source.to_string()),
                "__VERSION__" => Some(self.version.to_string()),
                _ => None,
            };
            if let Some(text) = dynamic {
                out.push(number_token(text, &t));
                continue;
            }
            let Some(m) = self.macros.get(&t.text) else {
                out.push(t);
                continue;
            };
            let m = m.clone();
            let mut body = match &m.params {
                None => m.body.clone(),
                Some(params) => {
                    let next = queue.iter().find_map(|i| match i {
                        Item::Tok(t) => Some(t),
                        Item::Pop => None,
                    });
                    if !is_punct(next, "(") {
                        out.push(t);
                        continue;
                    }
                    let Some(args) = self.arguments(&mut queue, active, &t) else { break };
                    let args =
                        if params.is_empty() && args.len() == 1 && args[0].is_empty() { Vec::new() } else { args };
                    if args.len() != params.len() {
                        self.log.preprocessor_error(
                            t.pos,
                            format!(
                                "macro `{}' invoked with {} arguments ({} expected)",
                                t.text,
                                args.len(),
                                params.len()
                            ),
                        );
                        break;
                    }
                    if depth >= MAX_ARGUMENT_DEPTH {
                        self.log.preprocessor_error(t.pos, "macro invocations nested too deeply in arguments");
                        self.exhausted = true;
                        break;
                    }
                    match self.substitute(&m.body, params, args, active, depth, t.pos) {
                        Some(body) => body,
                        None => break,
                    }
                }
            };
            if m.params.is_none() {
                for b in &mut body {
                    b.pos = t.pos;
                }
            }
            if let Some(first) = body.first_mut() {
                first.space_before = t.space_before;
            }
            self.expanded += body.len();
            if self.expanded > EXPANSION_BUDGET {
                self.log.preprocessor_error(t.pos, "macro expansion exceeds the implementation's limit");
                self.exhausted = true;
                break;
            }
            active.push(t.text.clone());
            queue.push_front(Item::Pop);
            for b in body.into_iter().rev() {
                queue.push_front(Item::Tok(b));
            }
        }
        active.truncate(base);
        out
    }

    /// The arguments of a function-like macro invocation, its `(` next in `queue`.
    fn arguments(
        &mut self,
        queue: &mut VecDeque<Item>,
        active: &mut Vec<String>,
        name: &PpToken,
    ) -> Option<Vec<Vec<PpToken>>> {
        let mut args = vec![Vec::new()];
        let mut depth = 0usize;
        let mut opened = false;
        while let Some(item) = queue.pop_front() {
            let t = match item {
                Item::Pop => {
                    active.pop();
                    continue;
                }
                Item::Tok(t) => t,
            };
            if !opened {
                opened = true; // the `(`
                continue;
            }
            if t.kind == PpKind::Punct {
                match t.text.as_str() {
                    "(" => depth += 1,
                    ")" if depth == 0 => return Some(args),
                    ")" => depth -= 1,
                    "," if depth == 0 => {
                        args.push(Vec::new());
                        continue;
                    }
                    _ => {}
                }
            }
            args.last_mut().expect("one argument at least").push(t);
        }
        self.log.preprocessor_error(name.pos, format!("unterminated invocation of macro `{}'", name.text));
        None
    }

    /// A function-like macro's body with its parameters replaced and `##` applied.
    fn substitute(
        &mut self,
        body: &[PpToken],
        params: &[String],
        args: Vec<Vec<PpToken>>,
        active: &[String],
        depth: usize,
        at: Pos,
    ) -> Option<Vec<PpToken>> {
        let mut expanded: Vec<Option<Vec<PpToken>>> = vec![None; args.len()];
        // Pieces: each a run of tokens; `##` joins the last token of one to the first of the next.
        let mut out: Vec<PpToken> = Vec::new();
        let mut paste_next = false;
        for (k, t) in body.iter().enumerate() {
            if t.kind == PpKind::Punct && t.text == "##" {
                paste_next = true;
                continue;
            }
            let beside_paste = paste_next || is_punct(body.get(k + 1), "##");
            let piece: Vec<PpToken> = match params.iter().position(|p| t.kind == PpKind::Ident && *p == t.text) {
                Some(i) if beside_paste => args[i].clone(),
                Some(i) => {
                    if expanded[i].is_none() {
                        let e = self.expand(args[i].clone(), &mut active.to_vec(), depth + 1);
                        expanded[i] = Some(e);
                    }
                    let mut piece = expanded[i].clone().unwrap_or_default();
                    if let Some(first) = piece.first_mut() {
                        first.space_before = t.space_before;
                    }
                    piece
                }
                None => vec![PpToken { pos: at, ..t.clone() }],
            };
            if paste_next && !piece.is_empty() && !out.is_empty() {
                let left = out.pop().expect("checked non-empty");
                let joined = format!("{}{}", left.text, piece[0].text);
                let mut scratch = InfoLog::default();
                let mut tokens = lex::tokenize(&joined, 0, &mut scratch);
                tokens.retain(|t| t.kind != PpKind::Newline);
                if tokens.len() != 1 || scratch.has_errors() {
                    self.log.preprocessor_error(
                        left.pos,
                        format!(
                            "pasting `{}' and `{}' does not give a valid preprocessing token",
                            left.text, piece[0].text
                        ),
                    );
                    return None;
                }
                out.push(PpToken {
                    kind: tokens[0].kind,
                    text: joined,
                    pos: left.pos,
                    space_before: left.space_before,
                    painted: false,
                });
                out.extend(piece.into_iter().skip(1));
            } else {
                out.extend(piece);
            }
            paste_next = false;
        }
        Some(out)
    }
}

/// The integer expression of `#if`: C's operators without `?:`, on 64-bit integers.
struct Eval<'a, 'l> {
    tokens: &'a [PpToken],
    at: usize,
    log: &'l mut InfoLog,
    version: u32,
    pos: Pos,
}

fn binary_precedence(op: &str) -> Option<u8> {
    Some(match op {
        "||" => 1,
        "&&" => 2,
        "|" => 3,
        "^" => 4,
        "&" => 5,
        "==" | "!=" => 6,
        "<" | ">" | "<=" | ">=" => 7,
        "<<" | ">>" => 8,
        "+" | "-" => 9,
        "*" | "/" | "%" => 10,
        _ => return None,
    })
}

impl Eval<'_, '_> {
    /// Reports an error at the end of the directive's line, where Mesa reports it.
    fn error<T>(&mut self, _at: Pos, message: String) -> Result<T, ()> {
        self.log.preprocessor_error(self.pos, message);
        Err(())
    }

    fn expr(&mut self, min: u8) -> Result<i64, ()> {
        let mut left = self.unary()?;
        while let Some(t) = self.tokens.get(self.at) {
            let Some(prec) = binary_precedence(&t.text).filter(|p| *p > min && t.kind == PpKind::Punct) else { break };
            let op = t.clone();
            self.at += 1;
            let right = self.expr(prec)?;
            left = match op.text.as_str() {
                "||" => (left != 0 || right != 0) as i64,
                "&&" => (left != 0 && right != 0) as i64,
                "|" => left | right,
                "^" => left ^ right,
                "&" => left & right,
                "==" => (left == right) as i64,
                "!=" => (left != right) as i64,
                "<" => (left < right) as i64,
                ">" => (left > right) as i64,
                "<=" => (left <= right) as i64,
                ">=" => (left >= right) as i64,
                "<<" => left.wrapping_shl(right as u32),
                ">>" => left.wrapping_shr(right as u32),
                "+" => left.wrapping_add(right),
                "-" => left.wrapping_sub(right),
                "*" => left.wrapping_mul(right),
                "/" | "%" if right == 0 => {
                    return self.error(op.pos, format!("division by zero in #if (`{}' by 0)", op.text));
                }
                "/" => left.wrapping_div(right),
                _ => left.wrapping_rem(right),
            };
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<i64, ()> {
        let Some(t) = self.tokens.get(self.at).cloned() else {
            let pos = self.tokens.last().map_or(self.pos, |t| t.pos);
            return self.error(pos, "syntax error in #if: the expression ends early".into());
        };
        self.at += 1;
        match (t.kind, t.text.as_str()) {
            (PpKind::Punct, "+") => self.unary(),
            (PpKind::Punct, "-") => Ok(self.unary()?.wrapping_neg()),
            (PpKind::Punct, "~") => Ok(!self.unary()?),
            (PpKind::Punct, "!") => Ok((self.unary()? == 0) as i64),
            (PpKind::Punct, "(") => {
                let v = self.expr(0)?;
                if !is_punct(self.tokens.get(self.at), ")") {
                    let pos = self.tokens.get(self.at).map_or(t.pos, |t| t.pos);
                    return self.error(pos, "syntax error in #if: missing `)'".into());
                }
                self.at += 1;
                Ok(v)
            }
            (PpKind::Number, text) => match lex::number(text, self.version) {
                TokenKind::Int(v) => Ok(v as i64),
                _ => self.error(t.pos, format!("`{text}' is not an integer constant in #if")),
            },
            // An identifier that is no macro is 0, as in C and in Mesa (GLSL 1.10/1.20
            // section 3.3 makes it an error; shaders written against Mesa rely on 0).
            (PpKind::Ident, _) => Ok(0),
            (_, text) => self.error(t.pos, format!("syntax error in #if: unexpected `{text}'")),
        }
    }
}
