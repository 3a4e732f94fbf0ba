//! The custom kernel of the filters family: the student's text read into
//! rows and a divisor, every error naming its field.

use super::*;

/// The largest custom kernel side, as in the `filter-window` example.
pub const MAX_CUSTOM_KERNEL: usize = 15;

/// A custom kernel typed by the student: rows separated by new lines or
/// `;`, numbers by spaces or `,`. `divisor` `None` normalises (divides by
/// the sum of the weights, added row by row). Returns the rows and the
/// divisor; every error names `custom_kernel` or `custom_divisor`.
pub fn custom_kernel(text: &str, divisor: Option<f64>) -> Result<(Vec<Vec<f64>>, f64)> {
    let field = "custom_kernel";
    let mut rows: Vec<Vec<f64>> = Vec::new();
    for line in text.split(['\n', ';']) {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let mut row = Vec::new();
        for token in line.split([' ', ',', '\t', '\r']).filter(|t| !t.is_empty()) {
            match token.parse::<f64>() {
                Ok(v) if v.is_finite() => row.push(v),
                _ => {
                    return Err(Error::input(
                        field,
                        format!("row {}: \"{token}\" is not a number", rows.len() + 1),
                    ))
                }
            }
        }
        if let Some(first) = rows.first() {
            if first.len() != row.len() {
                return Err(Error::input(
                    field,
                    format!(
                        "row {} has {} numbers but row 1 has {}; every row needs the same number",
                        rows.len() + 1,
                        row.len(),
                        first.len()
                    ),
                ));
            }
        }
        rows.push(row);
    }
    let (h, w) = (rows.len(), rows.first().map_or(0, Vec::len));
    if h == 0 {
        return Err(Error::input(
            field,
            "is empty; type rows of numbers, e.g. 1 2 1 / 2 4 2 / 1 2 1 on three lines",
        ));
    }
    if h > MAX_CUSTOM_KERNEL || w > MAX_CUSTOM_KERNEL {
        return Err(Error::input(
            field,
            format!("is {h}×{w} (rows × columns); at most {MAX_CUSTOM_KERNEL}×{MAX_CUSTOM_KERNEL} is allowed"),
        ));
    }
    if h % 2 == 0 || w % 2 == 0 {
        return Err(Error::input(
            field,
            format!("is {h}×{w} (rows × columns); a kernel needs an odd number of rows and of columns, so that it has a centre pixel"),
        ));
    }
    if rows.iter().flatten().all(|&v| v == 0.0) {
        return Err(Error::input(
            field,
            "all weights are 0: the result would be 0 everywhere",
        ));
    }
    let d = match divisor {
        Some(d) if d.is_finite() && d != 0.0 => d,
        Some(_) => {
            return Err(Error::input(
                "custom_divisor",
                "must be a finite number other than 0",
            ))
        }
        None => {
            let sum: f64 = rows.iter().flatten().sum();
            if sum == 0.0 {
                return Err(Error::input(
                    "custom_divisor",
                    "the weights sum to 0, so the kernel cannot be normalised; give a divisor (1 applies it as written)",
                ));
            }
            sum
        }
    };
    Ok((rows, d))
}
