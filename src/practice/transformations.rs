//! Practice for the transformations examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
