//! Practice for the interest examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
