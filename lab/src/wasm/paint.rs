//! Painting in the worker ([`crate::paint`]): a layer (or the photo) as a
//! `web_sys::ImageData` the worker draws and hands to the page as an
//! `ImageBitmap`, instead of a per-pixel JavaScript loop on the page.
//!
//! The layer's values are read from their `Float32Array` / `Float64Array`
//! in blocks (a 12-megapixel layer is never copied whole into wasm memory);
//! only the RGBA of the rows asked for is.

use super::*;

use crate::paint::{self, Ends, Range, Scale};
use js_sys::{Float32Array, Uint8ClampedArray};
use wasm_bindgen::JsCast;
use web_sys::ImageData;

/// Values read into wasm memory at a time.
const BLOCK: usize = 1 << 16;
/// The most pixels one painting may have (as the largest photo the lab opens, with room).
const MAX_PIXELS: usize = 1 << 27;

/// A layer's values as the worker holds them.
enum Values {
    F32(Float32Array),
    F64(Float64Array),
}

impl Values {
    fn of(data: &JsValue) -> Result<Values, JsError> {
        if let Some(a) = data.dyn_ref::<Float64Array>() {
            Ok(Values::F64(a.clone()))
        } else if let Some(a) = data.dyn_ref::<Float32Array>() {
            Ok(Values::F32(a.clone()))
        } else {
            Err(JsError::new(
                "data: must be a Float32Array or a Float64Array",
            ))
        }
    }

    fn len(&self) -> usize {
        match self {
            Values::F32(a) => a.length() as usize,
            Values::F64(a) => a.length() as usize,
        }
    }

    /// `f(block)` over the values, block by block, in order.
    fn blocks(&self, mut f: impl FnMut(Block)) {
        let n = self.len();
        match self {
            Values::F32(a) => {
                let mut buf = vec![0f32; BLOCK.min(n)];
                for i in (0..n).step_by(BLOCK) {
                    let j = (i + BLOCK).min(n);
                    a.subarray(i as u32, j as u32).copy_to(&mut buf[..j - i]);
                    f(Block::F32(&buf[..j - i]));
                }
            }
            Values::F64(a) => {
                let mut buf = vec![0f64; BLOCK.min(n)];
                for i in (0..n).step_by(BLOCK) {
                    let j = (i + BLOCK).min(n);
                    a.subarray(i as u32, j as u32).copy_to(&mut buf[..j - i]);
                    f(Block::F64(&buf[..j - i]));
                }
            }
        }
    }
}

enum Block<'a> {
    F32(&'a [f32]),
    F64(&'a [f64]),
}

fn ends_of(ends: &[u8]) -> Result<Ends, JsError> {
    match ends {
        [a, b, c, d, e, f] => Ok(Ends {
            negative: [*a, *b, *c],
            positive: [*d, *e, *f],
        }),
        _ => Err(JsError::new(
            "ends: must be six bytes, the negative and the positive end colour (RGB)",
        )),
    }
}

fn scale_js(s: &Scale) -> Result<JsValue, JsError> {
    obj(&[
        ("signed", JsValue::from_bool(s.signed)),
        ("lo", num(s.lo)),
        ("hi", num(s.hi)),
        ("min", num(s.min)),
        ("max", num(s.max)),
    ])
}

/// The smallest and largest finite values of `data` (a `Float32Array` or
/// `Float64Array`): `[min, max]`, `[Infinity, -Infinity]` when there is none
/// (ranges of a layer's parts fold with `Math.min` / `Math.max`).
#[wasm_bindgen]
pub fn layer_range(data: JsValue) -> Result<Float64Array, JsError> {
    let values = Values::of(&data)?;
    let mut r = Range::EMPTY;
    values.blocks(|b| {
        r = match b {
            Block::F32(v) => r.fold(v),
            Block::F64(v) => r.fold(v),
        }
    });
    Ok(Float64Array::from(&[r.min, r.max][..]))
}

/// `data` (`width` values a row) painted: `{ image: ImageData, scale:
/// { signed, lo, hi, min, max } }`. `signed`: the diverging scale about 0,
/// else the grey stretch; `ends`: the signed scale's end colours
/// `[r, g, b, r, g, b]` (negative, positive: colour-scales.js's);
/// `range`: `[min, max]` of the whole layer when `data` is a part of it
/// (each part painted on the whole's scale), else taken from `data`.
#[wasm_bindgen]
pub fn paint_layer(
    data: JsValue,
    width: usize,
    signed: bool,
    ends: &[u8],
    range: Option<Box<[f64]>>,
) -> Result<JsValue, JsError> {
    let values = Values::of(&data)?;
    let ends = ends_of(ends)?;
    let n = values.len();
    if width == 0 || n == 0 || n % width != 0 {
        return Err(JsError::new(&format!(
            "width: must divide the layer's {n} values into whole rows (got {width})"
        )));
    }
    if n > MAX_PIXELS {
        return Err(JsError::new(&format!(
            "data: {n} values are more than the {MAX_PIXELS} the lab paints"
        )));
    }
    let range = match range.as_deref() {
        None => {
            let mut r = Range::EMPTY;
            values.blocks(|b| {
                r = match b {
                    Block::F32(v) => r.fold(v),
                    Block::F64(v) => r.fold(v),
                }
            });
            r
        }
        Some(&[min, max]) if !min.is_nan() && !max.is_nan() => Range { min, max },
        Some(_) => return Err(JsError::new("range: must be [min, max], two numbers")),
    };
    let scale = Scale::new(range, signed);
    let mut rgba = vec![0u8; n * 4];
    let mut at = 0;
    values.blocks(|b| {
        let len = match b {
            Block::F32(v) => {
                paint::paint(v, &scale, &ends, &mut rgba[at * 4..(at + v.len()) * 4]);
                v.len()
            }
            Block::F64(v) => {
                paint::paint(v, &scale, &ends, &mut rgba[at * 4..(at + v.len()) * 4]);
                v.len()
            }
        };
        at += len;
    });
    // a copy in JS memory: an ImageData made on a view of wasm memory would
    // change with the next allocation there (and break when it grows)
    let pixels = Uint8ClampedArray::new_with_length((n * 4) as u32);
    pixels.copy_from(&rgba);
    drop(rgba);
    let image = ImageData::new_with_js_u8_clamped_array_and_sh(
        &pixels,
        width as u32,
        (n / width) as u32,
    )
    .map_err(|_| JsError::new("image: the browser could not make an ImageData of the layer"))?;
    obj(&[("image", image.into()), ("scale", scale_js(&scale)?)])
}
