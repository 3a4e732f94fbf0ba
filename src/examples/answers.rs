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
        "filter-window" => &["output"],
        "edge-window" => &["gx", "gy", "magnitude"],
        "forstner-window" => &["w", "q", "accepted"],
        "moravec-window" => &["sums", "mean"],
        "forstner-image" => &["w", "q", "points"],
        "chain-code" => &["code", "differential"],
        "boundary-length" => &["length"],
        "boundary-shape" => &["diameter", "minor_axis_length", "eccentricity"],
        "utm" => &["zone", "easting", "northing"],
        "utm-inverse" => &["latitude", "longitude"],
        _ => &[],
    }
}
