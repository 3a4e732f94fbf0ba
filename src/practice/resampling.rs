//! Practice for the resampling examples.

use super::Spec;

pub fn specs() -> Vec<Spec> {
    Vec::new()
}
