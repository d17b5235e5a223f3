//! Source positions and the info log: every message of the front end names the source
//! string, line and column it is about, and the log prints them as Mesa does
//! (`0:12(5): error: ...`), so that a program that greps a driver's info log reads ours.
//!
//! Columns count from 1 as Mesa counts them: in the preprocessor's output, where each run of
//! white space and comments is one space (so a tab or a comment counts one);
//! lines are as `#line` left them. A message is an error (the compile fails) or a warning,
//! each labelled as coming from the preprocessor or the compiler, as Mesa labels them.

use std::fmt;

/// Where a token or a construct starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Pos {
    /// The source string number (`#line`'s second operand; 0 unless changed).
    pub source: u32,
    pub line: u32,
    pub column: u32,
}

impl Pos {
    pub fn new(source: u32, line: u32, column: u32) -> Self {
        Pos { source, line, column }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    PreprocessorError,
    Warning,
    PreprocessorWarning,
}

impl Severity {
    fn label(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::PreprocessorError => "preprocessor error",
            Severity::Warning => "warning",
            Severity::PreprocessorWarning => "preprocessor warning",
        }
    }
}

/// One message of the info log.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    pub pos: Pos,
    pub severity: Severity,
    pub message: String,
}

impl Diagnostic {
    pub fn is_error(&self) -> bool {
        matches!(self.severity, Severity::Error | Severity::PreprocessorError)
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Pos { source, line, column } = self.pos;
        write!(f, "{source}:{line}({column}): {}: {}", self.severity.label(), self.message)
    }
}

/// The messages of one compile, in the order they were found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct InfoLog {
    pub diagnostics: Vec<Diagnostic>,
}

impl InfoLog {
    pub fn error(&mut self, pos: Pos, message: impl Into<String>) {
        self.push(pos, Severity::Error, message);
    }

    pub fn preprocessor_error(&mut self, pos: Pos, message: impl Into<String>) {
        self.push(pos, Severity::PreprocessorError, message);
    }

    pub fn warning(&mut self, pos: Pos, message: impl Into<String>) {
        self.push(pos, Severity::Warning, message);
    }

    pub fn preprocessor_warning(&mut self, pos: Pos, message: impl Into<String>) {
        self.push(pos, Severity::PreprocessorWarning, message);
    }

    fn push(&mut self, pos: Pos, severity: Severity, message: impl Into<String>) {
        self.diagnostics.push(Diagnostic { pos, severity, message: message.into() });
    }

    /// Whether the compile failed (any error; warnings do not count).
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(|d| d.is_error())
    }

    /// The first error, if any.
    pub fn first_error(&self) -> Option<&Diagnostic> {
        self.diagnostics.iter().find(|d| d.is_error())
    }

    /// The info log text as `glGetShaderInfoLog` returns it: one message a line.
    pub fn text(&self) -> String {
        let mut out = String::new();
        for d in &self.diagnostics {
            out.push_str(&d.to_string());
            out.push('\n');
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_print_as_mesa_prints_them() {
        let mut log = InfoLog::default();
        log.warning(Pos::new(0, 3, 1), "extension `GL_FOO' unsupported");
        assert!(!log.has_errors());
        log.error(Pos::new(0, 12, 5), "syntax error, unexpected ')'");
        log.preprocessor_error(Pos::new(2, 4, 1), "Unterminated #if");
        assert!(log.has_errors());
        assert_eq!(
            log.text(),
            "0:3(1): warning: extension `GL_FOO' unsupported\n\
             0:12(5): error: syntax error, unexpected ')'\n\
             2:4(1): preprocessor error: Unterminated #if\n"
        );
        assert_eq!(log.first_error().unwrap().pos.line, 12);
    }
}
