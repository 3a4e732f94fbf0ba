//! Practice for the filters examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
