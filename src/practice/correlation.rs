//! Practice for the correlation examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
