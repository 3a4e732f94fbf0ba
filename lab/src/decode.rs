//! Photos in: PNG, JPEG and TIFF decoded with the `image` crate under
//! [`image::Limits`], then turned into the core's [`Grid`] of grey values.
//!
//! Colour goes to grey by the ITU-R BT.601 luma weights,
//! `g = 0.299·R + 0.587·G + 0.114·B`, computed in `f64` on the stored
//! samples (no rounding to whole grey values; see [`luma`]): an 8-bit image gives grey values 0 … 255, a 16-bit
//! one 0 … 65535 (its precision kept). An alpha channel is ignored.
//!
//! Limits (a 2-core laptop with a browser tab survives them): at most
//! [`MAX_SIDE`] pixels across or down, at most [`MAX_PIXELS`] pixels in all
//! (the lab holds a grid of `f64`, 8 bytes a pixel, plus a few result
//! layers), and at most [`MAX_ALLOC`] bytes allocated by the decoder. A
//! header that claims more is refused before any pixel is decoded, which is
//! also what stops a decompression bomb (a tiny file that inflates to a
//! huge image).

use image::{DynamicImage, ImageError, ImageFormat, ImageReader, Limits};
use photogrammetry_playground::error::{Error, Result};
use photogrammetry_playground::raster::Grid;
use std::io::Cursor;

/// Largest width or height accepted (pixels).
pub const MAX_SIDE: u32 = 8192;
/// Largest number of pixels accepted (16 megapixels, e.g. 4096 × 4096).
pub const MAX_PIXELS: u64 = 16 * 1024 * 1024;
/// Largest allocation the decoder may make (bytes): a 16-megapixel RGBA
/// image at 16 bits is 128 MiB.
pub const MAX_ALLOC: u64 = 192 * 1024 * 1024;

/// A decoded photo as grey values, with what it was.
#[derive(Debug, Clone, PartialEq)]
pub struct Decoded {
    pub grid: Grid,
    /// `"PNG"`, `"JPEG"` or `"TIFF"`.
    pub format: &'static str,
    /// `"grey"` or `"colour"` (what the file stored).
    pub colour: &'static str,
    /// Bits per sample of the file: 8 or 16 (32 for float TIFF).
    pub bits: u32,
    /// The largest grey value the sample depth allows (255, 65535; 1 for float).
    pub max_value: f64,
}

/// The limits handed to the decoder.
pub fn limits() -> Limits {
    let mut l = Limits::default();
    l.max_image_width = Some(MAX_SIDE);
    l.max_image_height = Some(MAX_SIDE);
    l.max_alloc = Some(MAX_ALLOC);
    l
}

fn format_name(f: ImageFormat) -> Option<&'static str> {
    match f {
        ImageFormat::Png => Some("PNG"),
        ImageFormat::Jpeg => Some("JPEG"),
        ImageFormat::Tiff => Some("TIFF"),
        _ => None,
    }
}

/// Why `name` could not be read, in plain words.
fn explain(name: &str, format: &str, e: ImageError) -> Error {
    let reason = match e {
        ImageError::Limits(_) => format!(
            "the {format} image is too large to open here (at most {MAX_SIDE} pixels across or down, {} megapixels in all)",
            MAX_PIXELS / (1024 * 1024)
        ),
        ImageError::IoError(io) if io.kind() == std::io::ErrorKind::UnexpectedEof => {
            format!("the {format} file is cut short: it ends before the image does")
        }
        ImageError::IoError(io) => format!("the {format} file cannot be read: {io}"),
        ImageError::Unsupported(u) => {
            format!("uses a {format} feature the lab cannot read: {u}")
        }
        ImageError::Decoding(d) => format!("the {format} file is damaged: {d}"),
        ImageError::Parameter(p) => format!("the {format} file is not valid: {p}"),
        other => format!("the {format} file cannot be decoded: {other}"),
    };
    Error::input(name, reason)
}

/// Decodes `bytes` (a file called `name`, named in every error) into grey
/// values by the formula in the module docs.
pub fn decode(name: &str, bytes: &[u8]) -> Result<Decoded> {
    if bytes.is_empty() {
        return Err(Error::input(name, "the file is empty (0 bytes)"));
    }
    let guessed = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| Error::input(name, format!("cannot be read: {e}")))?;
    let Some(format) = guessed.format().and_then(format_name) else {
        let why = match guessed.format() {
            // an image, but of a format the lab has no decoder for
            Some(f) => format!(
                "is a {} image, a format the lab does not read: it opens PNG, JPEG and TIFF",
                f.extensions_str()
                    .first()
                    .map_or_else(|| format!("{f:?}"), |e| e.to_uppercase())
            ),
            None => "is not a PNG, JPEG or TIFF image (its first bytes are not the signature of any of them)".to_string(),
        };
        return Err(Error::input(name, why));
    };
    // The header first: its size is checked before any pixel is decoded.
    let mut reader = guessed;
    reader.limits(limits());
    let (w, h) = reader
        .into_dimensions()
        .map_err(|e| explain(name, format, e))?;
    if w == 0 || h == 0 {
        return Err(Error::input(
            name,
            format!("the {format} header says the image is {w}×{h} pixels: it has no pixels"),
        ));
    }
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(Error::input(
            name,
            format!(
                "the {format} header says {w}×{h} pixels ({:.1} megapixels); the lab opens at most {} megapixels",
                f64::from(w) * f64::from(h) / 1e6,
                MAX_PIXELS / (1024 * 1024)
            ),
        ));
    }
    if format == "JPEG" && !jpeg_complete(bytes) {
        // The JPEG decoder fills a cut-off scan with grey without a word.
        return Err(Error::input(
            name,
            "the JPEG file is cut short: it ends before the image does (no end-of-image marker after the last scan)",
        ));
    }
    let mut reader = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| Error::input(name, format!("cannot be read: {e}")))?;
    reader.limits(limits());
    let img = reader.decode().map_err(|e| explain(name, format, e))?;
    to_grey(name, format, img)
}

/// Whether a JPEG has its end-of-image marker (`FF D9`) after the start of
/// its last scan (`FF DA`); scan data never contains `FF D9` (a coded `FF`
/// is stuffed as `FF 00`).
fn jpeg_complete(bytes: &[u8]) -> bool {
    let last = |m: u8| bytes.windows(2).rposition(|w| w[0] == 0xFF && w[1] == m);
    match (last(0xDA), last(0xD9)) {
        (Some(sos), Some(eoi)) => eoi > sos,
        _ => false,
    }
}

/// BT.601 luma of one pixel's samples, as the whole-number sum
/// `299·R + 587·G + 114·B` (exact in `f64` for 8- and 16-bit samples)
/// divided by 1000 in one rounding: the grey value is the `f64` nearest the
/// exact luma, and it prints as at most three decimals (179.951, not
/// 179.95099999999996), so a window of a colour photo fits in an example's
/// URL ("explain this pixel").
pub fn luma(r: f64, g: f64, b: f64) -> f64 {
    (299.0 * r + 587.0 * g + 114.0 * b) / 1000.0
}

fn to_grey(name: &str, format: &'static str, img: DynamicImage) -> Result<Decoded> {
    let (w, h) = (img.width() as usize, img.height() as usize);
    let grey = |v: &[u16], step: usize| -> Vec<f64> {
        v.chunks_exact(step)
            .map(|p| luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
            .collect()
    };
    let (data, colour, bits, max_value): (Vec<f64>, _, _, _) = match img {
        DynamicImage::ImageLuma8(b) => {
            (b.iter().map(|&v| f64::from(v)).collect(), "grey", 8, 255.0)
        }
        DynamicImage::ImageLumaA8(b) => (
            b.chunks_exact(2).map(|p| f64::from(p[0])).collect(),
            "grey",
            8,
            255.0,
        ),
        DynamicImage::ImageLuma16(b) => (
            b.iter().map(|&v| f64::from(v)).collect(),
            "grey",
            16,
            65535.0,
        ),
        DynamicImage::ImageLumaA16(b) => (
            b.chunks_exact(2).map(|p| f64::from(p[0])).collect(),
            "grey",
            16,
            65535.0,
        ),
        DynamicImage::ImageRgb8(b) => (
            b.chunks_exact(3)
                .map(|p| luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
                .collect(),
            "colour",
            8,
            255.0,
        ),
        DynamicImage::ImageRgba8(b) => (
            b.chunks_exact(4)
                .map(|p| luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
                .collect(),
            "colour",
            8,
            255.0,
        ),
        DynamicImage::ImageRgb16(b) => (grey(b.as_raw(), 3), "colour", 16, 65535.0),
        DynamicImage::ImageRgba16(b) => (grey(b.as_raw(), 4), "colour", 16, 65535.0),
        DynamicImage::ImageRgb32F(b) => (
            b.chunks_exact(3)
                .map(|p| luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
                .collect(),
            "colour",
            32,
            1.0,
        ),
        DynamicImage::ImageRgba32F(b) => (
            b.chunks_exact(4)
                .map(|p| luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
                .collect(),
            "colour",
            32,
            1.0,
        ),
        other => {
            return Err(Error::input(
                name,
                format!(
                    "the {format} image stores its pixels as {:?}, which the lab cannot read",
                    other.color()
                ),
            ))
        }
    };
    let grid = Grid::new(name, w, h, data)?;
    Ok(Decoded {
        grid,
        format,
        colour,
        bits,
        max_value,
    })
}
