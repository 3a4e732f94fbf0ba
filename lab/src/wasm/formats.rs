//! The page's SIMD build decodes JPEG only (built without the `formats`
//! feature: scripts/build.sh), so that a lab visit downloads the other
//! decoders only when a photo needs them: the worker asks [`decodes_here`],
//! decodes any other file with the scalar build (which has every decoder)
//! and hands the result to this build with [`image_from_decoded`].

use super::*;

/// Whether this build decodes `bytes` itself: false for a format whose
/// decoder it leaves out (PNG, TIFF, WebP, BMP, GIF without the `formats`
/// feature). Files of no known format are this build's to refuse.
#[wasm_bindgen]
pub fn decodes_here(bytes: &[u8]) -> bool {
    image::guess_format(bytes).map_or(true, |f| f.reading_enabled())
}

/// An image decoded by another build of the lab: its `width × height`
/// grey values and what decoding said (`format`, `colour`, `bits`,
/// `max_value`; `photo`: `[orientation, photo width, photo height, factor]`,
/// as `LabImage.photo()` gives them), as this build's `LabImage`.
#[wasm_bindgen]
#[allow(clippy::too_many_arguments)]
pub fn image_from_decoded(
    width: usize,
    height: usize,
    grey: &[f64],
    format: JsValue,
    colour: JsValue,
    bits: u32,
    max_value: f64,
    photo: &[f64],
) -> Result<LabImage, JsError> {
    let format = string_arg("format", "naming a format", &format)?;
    let colour = string_arg("colour", "grey or colour", &colour)?;
    let [orientation, pw, ph, factor] = photo else {
        return Err(JsError::new(
            "photo: must be [orientation, width, height, factor]",
        ));
    };
    let whole = |v: f64| ((1.0..=1e9).contains(&v) && v.fract() == 0.0).then_some(v as usize);
    let (Some(o), Some(pw), Some(ph), Some(k)) =
        (whole(*orientation), whole(*pw), whole(*ph), whole(*factor))
    else {
        return Err(JsError::new(
            "photo: must be four whole numbers of at least 1",
        ));
    };
    if o > 8 {
        return Err(JsError::new("photo: the orientation must be 1 to 8"));
    }
    let mut img = bands::image_from_grey(width, height, grey, bits, max_value)?;
    img.format = format;
    img.colour = colour;
    img.photo = decode::Photo {
        orientation: o as u8,
        width: pw,
        height: ph,
        factor: k,
        work_width: width,
        work_height: height,
    };
    Ok(img)
}
