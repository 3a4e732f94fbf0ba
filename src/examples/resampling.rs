//! Resampling: the grey value at a fractional position of a patch (seed
//! 000, Examples 12a/12b; Lecture 7's cubic convolution). The example is
//! the file beside this one.

mod resample;

use super::{Example, Topic};

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[resample::EXAMPLE];

/// The topic: its module (`web/resampling/`) and title.
pub const TOPIC: Topic = Topic {
    module: "resampling",
    title: "Resampling",
    examples: EXAMPLES,
};
