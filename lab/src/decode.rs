//! Photos in: PNG, JPEG, TIFF, WebP, BMP and GIF (its first frame) decoded
//! with the `image` crate under [`image::Limits`], turned upright by their
//! EXIF orientation, reduced to the lab's working size when they are larger,
//! and made the core's [`Grid`] of grey values ([`grey`]). HEIC/HEIF, AVIF
//! and camera RAW files are recognised by their signatures and refused with
//! a way to a JPEG ([`sniff`]).
//!
//! Colour goes to grey by the ITU-R BT.601 luma weights,
//! `g = 0.299·R + 0.587·G + 0.114·B`, computed in `f64` on the stored
//! samples (no rounding to whole grey values; see [`luma`]): an 8-bit image gives grey values 0 … 255, a 16-bit
//! one 0 … 65535 (its precision kept). An alpha channel is ignored.
//!
//! Limits: a photo of at most [`MAX_SIDE`] pixels across or down and
//! [`MAX_PIXELS`] pixels in all (48 megapixels: an 8064 × 6048 camera photo
//! fits), and at most [`MAX_ALLOC`] bytes allocated by the decoder. A header
//! that claims more is refused before any pixel is decoded, which is also
//! what stops a decompression bomb (a tiny file that inflates to a huge
//! image). The lab works on at most [`WORK_PIXELS`] (16 megapixels: a grid
//! of `f64`, 8 bytes a pixel, plus a few result layers); a larger photo is
//! reduced by the smallest integer factor `k` that fits, each grey value the
//! area average of `k × k` photo pixels ([`Photo::reduced`] says so).

pub mod grey;
pub mod sniff;

use image::{ImageDecoder, ImageError, ImageFormat, ImageReader, Limits};
use photogrammetry_playground::error::{Error, Result};
use photogrammetry_playground::raster::Grid;
use std::io::Cursor;

/// Largest width or height of a photo accepted (pixels).
pub const MAX_SIDE: u32 = 16384;
/// Largest number of pixels of a photo accepted (48 megapixels of
/// 1024 × 1024 pixels: 50 331 648).
pub const MAX_PIXELS: u64 = 48 * 1024 * 1024;
/// The lab's working size: at most this many pixels (16 megapixels, e.g.
/// 4096 × 4096); a larger photo is reduced ([`reduction`]).
pub const WORK_PIXELS: u64 = 16 * 1024 * 1024;
/// Largest allocation the decoder may make (bytes): a 48-megapixel RGBA
/// image at 16 bits.
pub const MAX_ALLOC: u64 = MAX_PIXELS * 8;

/// What was done to a photo between its file and the lab's grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Photo {
    /// The EXIF orientation applied, 1 … 8 (1: none, or no tag).
    pub orientation: u8,
    /// The upright photo's width and height (before any reduction).
    pub width: usize,
    pub height: usize,
    /// The reduction factor `k`: one lab pixel is the area average of
    /// `k × k` photo pixels (1: not reduced).
    pub factor: usize,
    /// The lab's grid: `width / k × height / k` (whole blocks).
    pub work_width: usize,
    pub work_height: usize,
}

impl Photo {
    /// What the EXIF orientation did, in words (`None` for 1).
    pub fn turned(&self) -> Option<String> {
        let what = match self.orientation {
            2 => "mirrored left to right",
            3 => "turned 180°",
            4 => "mirrored top to bottom",
            5 => "turned 90° clockwise and mirrored left to right",
            6 => "turned 90° clockwise",
            7 => "turned 90° counter-clockwise and mirrored left to right",
            8 => "turned 90° counter-clockwise",
            _ => return None,
        };
        Some(format!(
            "{what} by its EXIF orientation ({})",
            self.orientation
        ))
    }

    /// The reduction to the working size, in words (`None` when not reduced).
    pub fn reduced(&self) -> Option<String> {
        let k = self.factor;
        if k == 1 {
            return None;
        }
        let left = match (
            !self.width.is_multiple_of(k),
            !self.height.is_multiple_of(k),
        ) {
            (true, true) => {
                " (the photo's last columns and rows that make no whole block left out)"
            }
            (true, false) => " (the photo's last columns that make no whole block left out)",
            (false, true) => " (the photo's last rows that make no whole block left out)",
            (false, false) => "",
        };
        Some(format!(
            "reduced {k}× (area average of {k} × {k} pixels) from {} × {} to {} × {} pixels to fit the lab's working size of {} megapixels{left}; 1 lab pixel = {k} × {k} photo pixels",
            self.width,
            self.height,
            self.work_width,
            self.work_height,
            WORK_PIXELS >> 20
        ))
    }
}

/// The smallest factor `k` whose whole `k × k` blocks of a `w × h` photo
/// fit the working size.
pub fn reduction(w: usize, h: usize) -> usize {
    (1..)
        .find(|&k| ((w / k) as u64) * ((h / k) as u64) <= WORK_PIXELS)
        .unwrap_or(1)
}

/// A decoded photo as grey values, with what it was.
#[derive(Debug, Clone, PartialEq)]
pub struct Decoded {
    pub grid: Grid,
    /// `"PNG"`, `"JPEG"`, `"TIFF"`, `"WebP"`, `"BMP"` or `"GIF"`.
    pub format: &'static str,
    /// `"grey"` or `"colour"` (what the file stored).
    pub colour: &'static str,
    /// Bits per sample of the file: 8 or 16 (32 for float TIFF).
    pub bits: u32,
    /// The largest grey value the sample depth allows (255, 65535; 1 for float).
    pub max_value: f64,
    /// Its orientation and reduction.
    pub photo: Photo,
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
        ImageFormat::WebP => Some("WebP"),
        ImageFormat::Bmp => Some("BMP"),
        ImageFormat::Gif => Some("GIF"),
        _ => None,
    }
}

/// The limits, in words.
fn limits_words() -> String {
    format!(
        "at most {MAX_SIDE} pixels across or down and {} megapixels in all",
        MAX_PIXELS >> 20
    )
}

/// Why `name` could not be read, in plain words.
fn explain(name: &str, format: &str, e: ImageError) -> Error {
    let reason = match e {
        ImageError::Limits(_) => format!(
            "the {format} image is too large to open here ({})",
            limits_words()
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

/// A decoder for `bytes` with its format's name and its [`Photo`], the
/// header checked (size, limits, a JPEG's end) and no pixel decoded.
#[allow(clippy::type_complexity)]
fn open<'b>(
    name: &str,
    bytes: &'b [u8],
) -> Result<(Box<dyn ImageDecoder + 'b>, &'static str, Photo)> {
    if bytes.is_empty() {
        return Err(Error::input(name, "the file is empty (0 bytes)"));
    }
    if let Some(why) = sniff::refused(name, bytes) {
        return Err(Error::input(name, why));
    }
    let guessed = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| Error::input(name, format!("cannot be read: {e}")))?;
    let Some(format) = guessed.format().and_then(format_name) else {
        let why = match guessed.format() {
            // an image, but of a format the lab has no decoder for
            Some(f) => format!(
                "is a {} image, a format the lab does not read: it opens PNG, JPEG, TIFF, WebP, BMP and GIF",
                f.extensions_str()
                    .first()
                    .map_or_else(|| format!("{f:?}"), |e| e.to_uppercase())
            ),
            None => "is not a PNG, JPEG or TIFF image, nor a WebP, BMP or GIF: its first bytes are not the signature of any format the lab reads".to_string(),
        };
        return Err(Error::input(name, why));
    };
    // a DNG that the TIFF decoder cannot read is refused as a RAW file
    let dng = format == "TIFF" && sniff::tiff(name, bytes) == sniff::Tiff::Dng;
    let explain = |e: ImageError| {
        if dng {
            Error::input(name, sniff::raw_message("DNG"))
        } else {
            explain(name, format, e)
        }
    };
    let mut reader = guessed;
    reader.limits(limits());
    // the header only: its size is checked before any pixel is decoded
    let mut decoder: Box<dyn ImageDecoder + 'b> = Box::new(reader.into_decoder().map_err(explain)?);
    let (w, h) = decoder.dimensions();
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
                "the {format} header says {w}×{h} pixels ({:.1} megapixels): too large to open here ({})",
                f64::from(w) * f64::from(h) / 1e6,
                limits_words()
            ),
        ));
    }
    if decoder.total_bytes() > MAX_ALLOC {
        return Err(explain(ImageError::Limits(
            image::error::LimitError::from_kind(image::error::LimitErrorKind::InsufficientMemory),
        )));
    }
    if format == "JPEG" && !jpeg_complete(bytes) {
        // The JPEG decoder fills a cut-off scan with grey without a word.
        return Err(Error::input(
            name,
            "the JPEG file is cut short: it ends before the image does (no end-of-image marker after the last scan)",
        ));
    }
    // a tag that cannot be read leaves the photo as stored, as a browser does
    let orientation = decoder.orientation().map_or(1, |o| o.to_exif());
    let (uw, uh) = grey::upright_size(orientation, w as usize, h as usize);
    let k = reduction(uw, uh);
    let photo = Photo {
        orientation,
        width: uw,
        height: uh,
        factor: k,
        work_width: uw / k,
        work_height: uh / k,
    };
    Ok((decoder, format, photo))
}

/// What `decode` would make of `bytes` (its format, orientation and
/// reduction), from the header only; the same errors as `decode` for a
/// file the lab refuses or a header it cannot read.
pub fn probe(name: &str, bytes: &[u8]) -> Result<(&'static str, Photo)> {
    open(name, bytes).map(|(_, format, photo)| (format, photo))
}

/// Decodes `bytes` (a file called `name`, named in every error) into grey
/// values by the formula in the module docs, upright and at the working
/// size.
pub fn decode(name: &str, bytes: &[u8]) -> Result<Decoded> {
    let (decoder, format, photo) = open(name, bytes)?;
    let dng = format == "TIFF" && sniff::tiff(name, bytes) == sniff::Tiff::Dng;
    let img = image::DynamicImage::from_decoder(decoder).map_err(|e| {
        if dng {
            Error::input(name, sniff::raw_message("DNG"))
        } else {
            explain(name, format, e)
        }
    })?;
    let out = (photo.work_width, photo.work_height);
    let Some((data, (colour, bits, max_value))) =
        grey::grey(&img, photo.orientation, photo.factor, out)
    else {
        return Err(Error::input(
            name,
            format!(
                "the {format} image stores its pixels as {:?}, which the lab cannot read",
                img.color()
            ),
        ));
    };
    drop(img);
    let grid = Grid::new(name, out.0, out.1, data)?;
    Ok(Decoded {
        grid,
        format,
        colour,
        bits,
        max_value,
        photo,
    })
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
