//! The course documents an example's `source` names, in full.

/// The course documents, in full, with the words a `source` names them by
/// (the old "Seed 00n" names too, so that a new entry written that way still
/// finds its document).
const DOCUMENTS: [(&[&str], &str); 3] = [
    (
        &["Worked examples", "Seed 000", "seed 000"],
        "Course notes — Worked examples 1–18 (digital image coordinates to boundary descriptors)",
    ),
    (
        &["Lecture 21", "Seed 003", "seed 003"],
        "Higher Surveying, Module 6, Lecture 21 — Image matching (Dr. Ajay Dashora, IIT Guwahati)",
    ),
    (
        &["Lecture 7", "Seed 004", "seed 004"],
        "Lecture 7 — Image processing (2017, after the lecture notes of Dr. Honda, AIT Thailand)",
    ),
];

/// The course document(s) an entry's `source` refers to, in full, in the
/// order the source names them (joined by "; "); "" when it names none.
pub fn document(source: &str) -> String {
    let mut found: Vec<(usize, &str)> = DOCUMENTS
        .iter()
        .filter_map(|(words, doc)| {
            words
                .iter()
                .filter_map(|w| source.find(w))
                .min()
                .map(|at| (at, *doc))
        })
        .collect();
    found.sort();
    found.iter().map(|(_, d)| *d).collect::<Vec<_>>().join("; ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn documents_follow_the_source_in_order() {
        assert!(document("Worked examples, Example 2").starts_with("Course notes — Worked"));
        let both = document("Lecture 21: Image matching; Worked examples, Example 13");
        assert!(both.starts_with("Higher Surveying"), "{both}");
        assert!(both.contains("; Course notes — Worked"), "{both}");
        assert!(document("Seed 004").starts_with("Lecture 7 — Image processing"));
        assert_eq!(document("nowhere"), "");
    }
}
