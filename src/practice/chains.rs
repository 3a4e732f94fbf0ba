//! Practice for the chains examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
