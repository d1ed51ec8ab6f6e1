//! One error family for the whole crate. Every failure a user can cause names what was wrong and
//! what is allowed; the CLI prints it on one line, the wasm binding turns it into a JS `Error`.

use core::fmt;

/// Everything that can go wrong in the library.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A parameter is out of its allowed range.
    Config(ConfigError),
    /// A text (URL value, command-line value, state string) does not name a valid value.
    Parse(ParseError),
    /// A requested duration or time step is invalid.
    InvalidDuration(f64),
    /// A linear-algebra step of the analysis failed (singular matrix, no Riccati solution, ...).
    Analysis(&'static str),
    /// Something asked for is not there yet (e.g. the stability maps are still being computed).
    NotReady(&'static str),
    /// A request the physics refuses, with the reason (e.g. a pole target no feedback reaches).
    Refused(String),
    /// The lesson's text does not follow its format (line number, 1-based, and what is wrong),
    /// or a lesson action does not apply (line 0).
    Lesson { line: usize, message: String },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Config(e) => e.fmt(f),
            Error::Parse(e) => e.fmt(f),
            Error::InvalidDuration(d) => {
                write!(f, "invalid duration = {d}: must be a finite number ≥ 0 s (at most 1e6 s)")
            }
            Error::Analysis(m) => write!(f, "analysis failed: {m}"),
            Error::NotReady(m) => write!(f, "{m}"),
            Error::Refused(m) => write!(f, "{m}"),
            Error::Lesson { line: 0, message } => write!(f, "lesson: {message}"),
            Error::Lesson { line, message } => write!(f, "lesson, line {line}: {message}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<ConfigError> for Error {
    fn from(e: ConfigError) -> Self {
        Error::Config(e)
    }
}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Self {
        Error::Parse(e)
    }
}

/// An invalid parameter: which one, its value, and what is allowed.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigError {
    /// The parameter's name, with the paper's symbol.
    pub parameter: &'static str,
    /// The rejected value.
    pub value: f64,
    /// The allowed range, in words.
    pub allowed: String,
}

impl ConfigError {
    pub fn new(parameter: &'static str, value: f64, allowed: &str) -> Self {
        Self { parameter, value, allowed: allowed.to_string() }
    }
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid {} = {}: {}", self.parameter, value_text(self.value), self.allowed)
    }
}

/// A rejected number as the user would write it: plain for ordinary magnitudes, with an
/// exponent for tiny and huge ones (1e-300, not three hundred zeros).
fn value_text(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e9).contains(&a) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

impl std::error::Error for ConfigError {}

/// A text that could not be read as a value of the parameter `key`.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// The parameter's key (URL key, CLI flag without dashes, JSON field).
    pub key: String,
    /// What was given.
    pub text: String,
    /// What is accepted, in words.
    pub expected: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Control characters in user text would garble a one-line message.
        let text: String = self.text.chars().map(|c| if c.is_control() { ' ' } else { c }).collect();
        // A range stated as a rule ("must be from …") reads as it is; a kind of value ("a number")
        // after "expected".
        let lead = if self.expected.starts_with("must ") { "" } else { "expected " };
        write!(f, "invalid {} = '{}': {lead}{}", self.key, text, self.expected)
    }
}

impl std::error::Error for ParseError {}

pub(crate) fn finite(name: &'static str, v: f64) -> Result<(), ConfigError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be a finite number"))
    }
}

pub(crate) fn positive(name: &'static str, v: f64) -> Result<(), ConfigError> {
    finite(name, v)?;
    if v > 0.0 {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be > 0"))
    }
}

pub(crate) fn non_negative(name: &'static str, v: f64) -> Result<(), ConfigError> {
    finite(name, v)?;
    if v >= 0.0 {
        Ok(())
    } else {
        Err(ConfigError::new(name, v, "must be ≥ 0"))
    }
}
