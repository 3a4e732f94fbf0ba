//! Practice for the matching examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
