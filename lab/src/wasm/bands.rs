//! What the lab's pool of workers needs beyond the operators' own exports
//! (www/lab/tiles.js): Förstner's map is computed by bands of rows, each
//! band keeping its own map for the live threshold, and the photo's
//! automatic threshold is then found once over the whole `w` layer here,
//! on the main worker's photo ([`ops::exact_w_min`]: the number one
//! whole-image map gives).

use super::*;

use photogrammetry_playground::interest::fast::stream;

/// The threshold chosen for the photo `img` (8-bit) from its whole `w`
/// layer `w` (`f32`, the photo's size, as the bands put it together) for
/// `size × size` windows and `σn`: `{ thresholdPx, wMin, share }` (as
/// `ForstnerMaps.auto_threshold`), or null when no pixel is textured.
#[wasm_bindgen]
pub fn forstner_auto_threshold(
    img: &LabImage,
    size: usize,
    w: &[f32],
    sigma_n: f64,
) -> Result<JsValue, JsError> {
    let (width, height) = (img.grid.width(), img.grid.height());
    if w.len() != width * height {
        return Err(JsError::new(&format!(
            "w: must hold the photo's {} values (got {})",
            width * height,
            w.len()
        )));
    }
    let Some(bytes) = img.bytes.get_or_init(|| img.grid.to_u8()).as_deref() else {
        return Err(JsError::new(
            "image: the bands' threshold needs an 8-bit photo",
        ));
    };
    let fit = stream::fit(width, height, size).map_err(js_error)?;
    let w_min = ops::exact_w_min(bytes, width, height, size, w, fit);
    match w_min {
        Some(w_min) if w_min > 0.0 && sigma_n > 0.0 => obj(&[
            ("thresholdPx", num(sigma_n / w_min.sqrt())),
            ("wMin", num(w_min)),
            ("share", num(ops::W_TOP_SHARE)),
        ]),
        _ => Ok(JsValue::NULL),
    }
}

/// A grey image of `width × height` `values` (row-major) with the sample
/// depth of the photo it comes from (`bits`, `max_value`): a band of a
/// photo that is not 8-bit (a colour photo's BT.601 greys, 16-bit values),
/// which the pool's workers run as the main worker runs the whole photo.
#[wasm_bindgen]
pub fn image_from_grey(
    width: usize,
    height: usize,
    values: &[f64],
    bits: u32,
    max_value: f64,
) -> Result<LabImage, JsError> {
    if values.iter().any(|v| !v.is_finite()) {
        return Err(JsError::new("values: must be finite numbers"));
    }
    if !(max_value.is_finite() && max_value > 0.0 && (1..=32).contains(&bits)) {
        return Err(JsError::new(
            "bits: must be 1 to 32, and max_value a number above 0",
        ));
    }
    let g = Grid::new("image", width, height, values.to_vec()).map_err(js_error)?;
    Ok(wrap(g, "raw", "grey", bits, max_value))
}

/// The `w × h` box of `img` from `(c, r)` as an image of its own (a
/// preview's part with its halo), its bytes with it when it is 8-bit. With
/// `eight_bit`, a photo that is not 8-bit (a colour photo's BT.601 greys,
/// 16-bit values) comes rounded to 8 bits (`round(v · 255 / max_value)`),
/// so that its preview takes the operators' fast paths: a preview, not the
/// result's exact numbers.
#[wasm_bindgen]
pub fn crop_image(
    img: &LabImage,
    c: usize,
    r: usize,
    w: usize,
    h: usize,
    eight_bit: Option<bool>,
) -> Result<LabImage, JsError> {
    let g = img
        .grid
        .window(c, r, w, h)
        .filter(|g| g.width() > 0 && g.height() > 0)
        .ok_or_else(|| JsError::new("crop: the box must lie inside the image"))?;
    let width = img.grid.width();
    match img.bytes.get_or_init(|| img.grid.to_u8()) {
        Some(bytes) => {
            let out = wrap(g, &img.format, &img.colour, img.bits, img.max_value);
            let part: Vec<u8> = (r..r + h)
                .flat_map(|y| bytes[y * width + c..y * width + c + w].iter().copied())
                .collect();
            let _ = out.bytes.set(Some(part));
            Ok(out)
        }
        None if eight_bit == Some(true) => {
            let k = 255.0 / img.max_value;
            let part: Vec<u8> = g
                .data()
                .iter()
                .map(|&v| (v * k).round().clamp(0.0, 255.0) as u8)
                .collect();
            let g8 = Grid::new("image", w, h, part.iter().map(|&v| f64::from(v)).collect())
                .map_err(js_error)?;
            let out = wrap(g8, &img.format, &img.colour, 8, 255.0);
            let _ = out.bytes.set(Some(part));
            Ok(out)
        }
        None => Ok(wrap(g, &img.format, &img.colour, img.bits, img.max_value)),
    }
}
