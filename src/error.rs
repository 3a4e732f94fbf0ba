//! The one error type of the crate. Every failure a user can cause is a value
//! of [`Error`] with a message that names the field and says what is wrong;
//! nothing in the crate panics on user input.

use std::fmt;

/// Everything that can go wrong, with enough context for a readable message.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// `solve` or `parse_inputs` was given an id that is not in the catalog.
    UnknownExample { id: String },
    /// The example is listed in the catalog but not built yet.
    NotBuilt { id: String },
    /// An input key that the example does not have.
    UnknownField { field: String, known: Vec<String> },
    /// An input value of the wrong type, shape or range.
    InvalidInput { field: String, reason: String },
    /// A least-squares system with fewer observations than unknowns.
    TooFewObservations { needed: usize, given: usize },
    /// A system whose parameters cannot be determined (rank-deficient or
    /// numerically singular), with the reason.
    Singular { reason: String },
    /// An iteration that did not converge within its limit.
    NotConverged {
        what: String,
        iterations: usize,
        detail: String,
    },
    /// A bug: a result that should not be possible (NaN in a result, a
    /// missing validated field). Reported instead of panicking.
    Internal(String),
}

impl Error {
    /// Shorthand for [`Error::InvalidInput`].
    pub fn input(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::InvalidInput {
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// The same error, said of input field `field` (a singular system of
    /// `points` is a problem with the points).
    pub fn in_field(self, field: &str) -> Self {
        match self {
            Error::InvalidInput { .. } | Error::UnknownField { .. } | Error::Internal(_) => self,
            other => Error::InvalidInput {
                field: field.to_string(),
                reason: other.to_string(),
            },
        }
    }

    /// The input field the error is about, if it is about one.
    pub fn field(&self) -> Option<&str> {
        match self {
            Error::UnknownField { field, .. } | Error::InvalidInput { field, .. } => Some(field),
            _ => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::UnknownExample { id } => {
                write!(f, "unknown example id \"{id}\" (see catalog() for the ids)")
            }
            Error::NotBuilt { id } => write!(f, "example \"{id}\" is not built yet"),
            Error::UnknownField { field, known } => write!(
                f,
                "{field}: unknown field (this example takes: {})",
                known.join(", ")
            ),
            Error::InvalidInput { field, reason } => write!(f, "{field}: {reason}"),
            Error::TooFewObservations { needed, given } => write!(
                f,
                "too few observations: {needed} are needed, {given} given ({} more needed)",
                needed - given.min(needed)
            ),
            Error::Singular { reason } => write!(f, "the system cannot be solved: {reason}"),
            Error::NotConverged {
                what,
                iterations,
                detail,
            } => write!(
                f,
                "{what} did not converge in {iterations} iterations: {detail}"
            ),
            Error::Internal(msg) => write!(f, "internal error (please report): {msg}"),
        }
    }
}

impl std::error::Error for Error {}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;
