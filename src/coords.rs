//! Pixel and image coordinates, pixel size from scan resolution, photo scale
//! and ground sample distance (seed 000, Examples 1–3).
//!
//! Conventions (the seed's): pixel coordinates `c` (column, to the right) and
//! `r` (row, downward) with the origin at the image's top-left corner; image
//! coordinates `x` (right) and `y` (up) in millimetres with the origin at the
//! image centre `(columns/2, rows/2)`.

use crate::error::{Error, Result};

/// Millimetres in one inch.
pub const MM_PER_INCH: f64 = 25.4;

/// Pixel size in mm of a scan at `dpi` dots per inch: `p = 25.4 / dpi`.
pub fn pixel_size_mm(dpi: f64) -> Result<f64> {
    if !(dpi.is_finite() && dpi > 0.0) {
        return Err(Error::input("dpi", "must be a positive number"));
    }
    Ok(MM_PER_INCH / dpi)
}

/// The size of a digital image in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub columns: f64,
    pub rows: f64,
}

impl Frame {
    /// The image centre in pixel coordinates: `(columns/2, rows/2)`.
    pub fn centre(&self) -> (f64, f64) {
        (self.columns / 2.0, self.rows / 2.0)
    }
    /// True when `(c, r)` lies on the image (edges included).
    pub fn contains(&self, c: f64, r: f64) -> bool {
        (0.0..=self.columns).contains(&c) && (0.0..=self.rows).contains(&r)
    }
}

/// Pixel coordinates to image coordinates, with every intermediate.
#[derive(Debug, Clone, PartialEq)]
pub struct PixelToImage {
    pub c0: f64,
    pub r0: f64,
    /// `c - c0`, in pixels.
    pub x_px: f64,
    /// `-(r - r0)`, in pixels.
    pub y_px: f64,
    pub pixel_size_mm: f64,
    pub x_mm: f64,
    pub y_mm: f64,
    pub inside: bool,
}

/// `x = (c - c0)·p`, `y = -(r - r0)·p`.
pub fn pixel_to_image(dpi: f64, frame: Frame, c: f64, r: f64) -> Result<PixelToImage> {
    let p = pixel_size_mm(dpi)?;
    let (c0, r0) = frame.centre();
    let x_px = c - c0;
    let y_px = -(r - r0);
    Ok(PixelToImage {
        c0,
        r0,
        x_px,
        y_px,
        pixel_size_mm: p,
        x_mm: x_px * p,
        y_mm: y_px * p,
        inside: frame.contains(c, r),
    })
}

/// Image coordinates to pixel coordinates, with every intermediate.
#[derive(Debug, Clone, PartialEq)]
pub struct ImageToPixel {
    pub c0: f64,
    pub r0: f64,
    pub pixel_size_mm: f64,
    /// Column offset from the centre, `x / p`.
    pub dc_px: f64,
    /// Row offset from the centre, `-y / p` (rows count downward).
    pub dr_px: f64,
    pub c: f64,
    pub r: f64,
    pub inside: bool,
}

/// `c = c0 + x/p`, `r = r0 - y/p`.
pub fn image_to_pixel(dpi: f64, frame: Frame, x_mm: f64, y_mm: f64) -> Result<ImageToPixel> {
    let p = pixel_size_mm(dpi)?;
    let (c0, r0) = frame.centre();
    let dc_px = x_mm / p;
    let dr_px = -y_mm / p;
    let (c, r) = (c0 + dc_px, r0 + dr_px);
    Ok(ImageToPixel {
        c0,
        r0,
        pixel_size_mm: p,
        dc_px,
        dr_px,
        c,
        r,
        inside: frame.contains(c, r),
    })
}

/// Photo scale and ground sample distance, with every intermediate.
#[derive(Debug, Clone, PartialEq)]
pub struct Gsd {
    /// `m` in the scale `1 : m`, `m = H / f` (both in metres).
    pub scale_denominator: f64,
    pub pixel_size_mm: f64,
    /// The ground size of one pixel, `p · m`, in mm.
    pub gsd_mm: f64,
}

/// Ground sample distance of a vertical photo scanned at `dpi`, taken with
/// focal length `focal_length_mm` from `flying_height_m` above the ground.
pub fn gsd(dpi: f64, focal_length_mm: f64, flying_height_m: f64) -> Result<Gsd> {
    let p = pixel_size_mm(dpi)?;
    if !(focal_length_mm.is_finite() && focal_length_mm > 0.0) {
        return Err(Error::input("focal_length_mm", "must be a positive number"));
    }
    if !(flying_height_m.is_finite() && flying_height_m > 0.0) {
        return Err(Error::input("flying_height_m", "must be a positive number"));
    }
    let m = flying_height_m / (focal_length_mm / 1000.0);
    Ok(Gsd {
        scale_denominator: m,
        pixel_size_mm: p,
        gsd_mm: p * m,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_and_image_coordinates_are_inverse() {
        let frame = Frame {
            columns: 1600.0,
            rows: 1400.0,
        };
        let a = pixel_to_image(600.0, frame, 995.0, 480.0).unwrap();
        let b = image_to_pixel(600.0, frame, a.x_mm, a.y_mm).unwrap();
        assert!((b.c - 995.0).abs() < 1e-9 && (b.r - 480.0).abs() < 1e-9);
    }

    #[test]
    fn gsd_is_linear_in_height() {
        let a = gsd(900.0, 152.0, 1000.0).unwrap();
        let b = gsd(900.0, 152.0, 2000.0).unwrap();
        assert!((b.gsd_mm - 2.0 * a.gsd_mm).abs() < 1e-9);
    }

    #[test]
    fn rejects_non_positive_resolution() {
        assert!(pixel_size_mm(0.0).is_err());
        assert!(pixel_size_mm(f64::NAN).is_err());
        assert!(gsd(900.0, 0.0, 1.0).is_err());
    }
}
