//! What the lab's pool of workers needs beyond the operators' own exports
//! (www/lab/tiles.js): Förstner's map is computed by bands of rows, each
//! band keeping its own map for the live threshold, and the photo's
//! automatic threshold is then found once over the whole `w` layer here,
//! on the main worker's photo (the number one whole-image map gives).

use super::*;

use photogrammetry_playground::interest::{self, fast::stream};

/// The threshold chosen for the photo `img` from its whole `w` layer `w`
/// (`f32`, the photo's size, NaN where no window fits, as the bands put it
/// together) for `size × size` windows and `σn`: `{ thresholdPx, wMin,
/// share }` (as `ForstnerMaps.auto_threshold`), or null when no pixel is
/// textured. `w_min` is the one whole-image map gives: on an 8-bit photo
/// [`ops::exact_w_min`] (the fast route's sums), on a colour photo's levels
/// [`ops::levels_w_min`], otherwise the `w` of rank
/// [`ops::top_rank`] found on the layer (rounding keeps the order) and the
/// windows whose `f32` is that value recomputed by `interest::forstner`.
#[wasm_bindgen]
pub fn forstner_auto_threshold(
    img: &LabImage,
    size: usize,
    w: &[f32],
    sigma_n: f64,
) -> Result<JsValue, JsError> {
    let (width, height) = (img.width, img.height);
    if w.len() != width * height {
        return Err(JsError::new(&format!(
            "w: must hold the photo's {} values (got {})",
            width * height,
            w.len()
        )));
    }
    let fit = stream::fit(width, height, size).map_err(js_error)?;
    let w_min = match img.bytes() {
        Some(bytes) => ops::exact_w_min(bytes, width, height, size, w, fit),
        None => {
            // a colour photo's levels: the layer's w are within their error of the reference's
            let levels = ops::Image::with_bytes(img.grid(), None).with_levels(&img.levels);
            match levels.levels() {
                Some(lv) => ops::levels_w_min(lv, width, height, size, w),
                None => reference_w_min(img.grid(), size, w),
            }
        }
    };
    match w_min {
        Some(w_min) if w_min > 0.0 && sigma_n > 0.0 => obj(&[
            ("thresholdPx", num(sigma_n / w_min.sqrt())),
            ("wMin", num(w_min)),
            ("share", num(ops::W_TOP_SHARE)),
        ]),
        _ => Ok(JsValue::NULL),
    }
}

/// The reference route's `w_min` (the `w` of rank [`ops::top_rank`] among
/// the windows that fit) from the `f32` layer `w` and the windows of its
/// rank's value recomputed exactly.
fn reference_w_min(grid: &Grid, size: usize, w: &[f32]) -> Option<f64> {
    let mut all: Vec<f32> = w.iter().copied().filter(|v| !v.is_nan()).collect();
    if all.is_empty() {
        return None;
    }
    let k = ops::top_rank(all.len());
    let v = *all.select_nth_unstable_by(k, f32::total_cmp).1;
    let below = all.iter().filter(|&&x| x < v).count();
    drop(all);
    let width = grid.width();
    let mut group: Vec<f64> = w
        .iter()
        .enumerate()
        .filter(|(_, &x)| x == v)
        .filter_map(|(i, _)| {
            let win = interest::window_at(grid, i % width, i / width, size)?;
            Some(interest::forstner(&win).ok()?.measures.w)
        })
        .collect();
    group.sort_by(f64::total_cmp);
    group.get(k.checked_sub(below)?).copied()
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

/// A band of a colour photo as its levels (`levels`: `width × height`
/// whole numbers `n`, each grey `n / scale`; what [`image_levels`] gives
/// the page once per photo), with the photo's sample depth: the pool's
/// workers run it as the main worker runs the whole photo, without an
/// `f64` grid (one is built from the levels only if a reference path asks)
/// and without finding the levels again. Half the bytes of the greys.
#[wasm_bindgen]
pub fn image_from_levels(
    width: usize,
    height: usize,
    levels: &[f32],
    scale: f64,
    bits: u32,
    max_value: f64,
) -> Result<LabImage, JsError> {
    if !(max_value.is_finite() && max_value > 0.0 && (1..=32).contains(&bits)) {
        return Err(JsError::new(
            "bits: must be 1 to 32, and max_value a number above 0",
        ));
    }
    let l = ops::Levels::new(levels.to_vec(), scale).map_err(js_error)?;
    photogrammetry_playground::raster::GrayF32::new("levels", &l.data, width, height)
        .map_err(js_error)?;
    let img = bare(width, height, "raw", "grey", bits, max_value);
    let _ = img.levels.set(Some(l));
    let _ = img.bytes.set(None);
    Ok(img)
}

/// The photo's grey values as levels, found once (and kept with it):
/// `{ levels: Float32Array, scale }` when they are whole numbers over one
/// scale and not 8-bit (a colour photo's BT.601 greys, 16-bit values),
/// else `undefined` — what the page cuts into bands for
/// [`image_from_levels`].
#[wasm_bindgen]
pub fn image_levels(img: &LabImage) -> Result<JsValue, JsError> {
    if img.bytes().is_some() {
        return Ok(JsValue::UNDEFINED);
    }
    let image = ops::Image::with_bytes(img.grid(), None).with_levels(&img.levels);
    match image.levels() {
        Some(l) => obj(&[
            ("levels", js_sys::Float32Array::from(&l.data[..]).into()),
            ("scale", num(l.scale)),
        ]),
        None => Ok(JsValue::UNDEFINED),
    }
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
    let inside = w > 0 && h > 0 && c.checked_add(w).is_some_and(|e| e <= img.width);
    if !(inside && r.checked_add(h).is_some_and(|e| e <= img.height)) {
        return Err(JsError::new("crop: the box must lie inside the image"));
    }
    let width = img.width;
    if let Some(bytes) = img.bytes() {
        // (its bytes only: the grid is built if a reference path asks for it)
        let part: Vec<u8> = (r..r + h)
            .flat_map(|y| bytes[y * width + c..y * width + c + w].iter().copied())
            .collect();
        let mut out = bare(w, h, &img.format, &img.colour, img.bits, img.max_value);
        out.bytes = std::cell::OnceCell::from(Some(part));
        return Ok(out);
    }
    let g = img
        .grid()
        .window(c, r, w, h)
        .ok_or_else(|| JsError::new("crop: the box must lie inside the image"))?;
    if eight_bit == Some(true) {
        let k = 255.0 / img.max_value;
        let part: Vec<u8> = g
            .data()
            .iter()
            .map(|&v| (v * k).round().clamp(0.0, 255.0) as u8)
            .collect();
        let mut out = bare(w, h, &img.format, &img.colour, 8, 255.0);
        out.bytes = std::cell::OnceCell::from(Some(part));
        return Ok(out);
    }
    Ok(wrap(g, &img.format, &img.colour, img.bits, img.max_value))
}
