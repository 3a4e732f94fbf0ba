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
