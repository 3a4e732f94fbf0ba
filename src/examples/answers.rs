//! The answer of each worked example: the one to three result keys the page
//! writes in its answer line near the top ("GSD = 35.65 cm; the course notes
//! print 35.37 cm"). One table, so that every example has one.

/// The answer keys of example `id` (empty for an unknown id).
pub fn keys(id: &str) -> &'static [&'static str] {
    match id {
        "pixel-to-photo" => &["x_mm", "y_mm"],
        "gsd" => &["gsd_cm"],
        "photo-to-pixel" => &["c", "r"],
        "fiducial-similarity" | "fiducial-affine" | "transform-fit" => &["parameters", "sigma0"],
        "ncc-1d" => &["best", "best_c"],
        "ncc-2d" => &["rho"],
        "ncc-surface" => &["best_position", "best_c", "best_r"],
        "subpixel-1d" => &["c_max"],
        "subpixel-2d" => &["c_max", "r_max"],
        "lsm-1d" => &["c"],
        "lsm-2d" => &["c", "r"],
        "lsm-affine" => &["parameters", "sigma0"],
        "resample" => &["nearest", "bilinear", "bicubic"],
        // the selected pixel first: the number the image lab explains
        "filter-window" => &["selected", "output"],
        "edge-window" => &["selected_gx", "selected_gy", "selected_magnitude"],
        "forstner-window" => &["w", "q", "accepted"],
        "moravec-window" => &["sums", "mean"],
        "forstner-image" => &["w", "q", "points"],
        "chain-code" => &["code", "differential"],
        "boundary-length" => &["length"],
        "boundary-shape" => &["diameter", "minor_axis_length", "eccentricity"],
        "utm" => &["zone", "easting", "northing"],
        "utm-inverse" => &["latitude", "longitude"],
        "utm-facts" => &["k1_distance_km", "latitude_max", "edge_distortion_ppm"],
        _ => &[],
    }
}

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
