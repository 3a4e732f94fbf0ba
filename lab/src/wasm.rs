//! The lab's wasm-bindgen boundary: thin exports over [`crate::decode`],
//! [`crate::sample`] and [`crate::ops`]. Images stay in wasm memory as
//! [`LabImage`]; result layers leave as `Float32Array`s (one copy each),
//! which the worker posts to the page as transferables. Every error is a
//! thrown JS `Error` whose message names the field or the file; a string
//! argument is taken as a `JsValue` and checked (`wasm::string_arg`), so that
//! a wrong type is such an error, never a trap.

use crate::decode;
use crate::ops::{self, Layer, Point, Rect};
use crate::sample;
use js_sys::{Array, Float64Array, Object, Reflect};
use photogrammetry_playground::error::Error;
use photogrammetry_playground::filter;
use photogrammetry_playground::matching::{Model, Status};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::resample::Method;
use photogrammetry_playground::wasm::string_arg;
use wasm_bindgen::prelude::*;

fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

fn obj(fields: &[(&str, JsValue)]) -> Result<JsValue, JsError> {
    let o = Object::new();
    for (k, v) in fields {
        Reflect::set(&o, &JsValue::from_str(k), v)
            .map_err(|_| JsError::new("internal error (please report): cannot build a result"))?;
    }
    Ok(o.into())
}

fn num(x: f64) -> JsValue {
    JsValue::from_f64(x)
}

fn layer_js(l: &Layer) -> Result<JsValue, JsError> {
    obj(&[
        ("name", JsValue::from_str(&l.name)),
        ("width", num(l.width as f64)),
        ("height", num(l.height as f64)),
        ("c0", num(l.c0 as f64)),
        ("r0", num(l.r0 as f64)),
        ("signed", JsValue::from_bool(l.signed)),
        ("data", Float64Array::from(l.data.as_slice()).into()),
    ])
}

fn layers_js(ls: &[Layer]) -> Result<JsValue, JsError> {
    let a = Array::new();
    for l in ls {
        a.push(&layer_js(l)?);
    }
    Ok(a.into())
}

fn grid_layer(name: &str, g: &Grid, c0: usize, r0: usize, signed: bool) -> Layer {
    Layer {
        name: name.to_string(),
        width: g.width(),
        height: g.height(),
        c0,
        r0,
        data: g.data().to_vec(),
        signed,
    }
}

fn points_js(ps: &[Point]) -> JsValue {
    let flat: Vec<f64> = ps
        .iter()
        .flat_map(|p| [p.c as f64, p.r as f64, p.score, p.major, p.minor, p.angle])
        .collect();
    Float64Array::from(flat.as_slice()).into()
}

/// A grey image held in wasm memory.
#[wasm_bindgen]
pub struct LabImage {
    grid: Grid,
    format: String,
    colour: String,
    bits: u32,
    max_value: f64,
}

#[wasm_bindgen]
impl LabImage {
    pub fn width(&self) -> usize {
        self.grid.width()
    }
    pub fn height(&self) -> usize {
        self.grid.height()
    }
    /// `PNG`, `JPEG`, `TIFF`, `generated` or `raw`.
    pub fn format(&self) -> String {
        self.format.clone()
    }
    /// `grey` or `colour` (what the file stored).
    pub fn colour(&self) -> String {
        self.colour.clone()
    }
    pub fn bits(&self) -> u32 {
        self.bits
    }
    /// The largest grey value the sample depth allows.
    pub fn max_value(&self) -> f64 {
        self.max_value
    }
    /// The grey values, row-major (one copy out of wasm memory).
    pub fn grey(&self) -> Float64Array {
        Float64Array::from(self.grid.data())
    }
    /// The `w × h` neighbourhood centred on `(c, r)` read under `border`
    /// (`filter::neighbourhood`), row-major: the window a worked example
    /// gets for that pixel.
    pub fn neighbourhood(
        &self,
        c: usize,
        r: usize,
        w: usize,
        h: usize,
        border: JsValue,
    ) -> Result<Float64Array, JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        filter::neighbourhood(&self.grid, c, r, w, h, b)
            .map(|v| Float64Array::from(v.as_slice()))
            .ok_or_else(|| JsError::new("window: part of it lies outside the image (border crop)"))
    }
    /// The grey value at `(c, r)`, `undefined` outside.
    pub fn value(&self, c: usize, r: usize) -> Option<f64> {
        self.grid.get(c, r)
    }
    /// The `w × h` window with top-left `(c, r)`, row-major (`Float64Array`).
    pub fn window(&self, c: usize, r: usize, w: usize, h: usize) -> Result<Float64Array, JsError> {
        self.grid
            .window(c, r, w, h)
            .map(|g| Float64Array::from(g.data()))
            .ok_or_else(|| JsError::new("window: does not lie inside the image"))
    }
}

fn wrap(grid: Grid, format: &str, colour: &str, bits: u32, max_value: f64) -> LabImage {
    LabImage {
        grid,
        format: format.into(),
        colour: colour.into(),
        bits,
        max_value,
    }
}

/// Decodes a PNG, JPEG or TIFF file to grey values (BT.601 luma).
#[wasm_bindgen]
pub fn decode_image(name: JsValue, bytes: &[u8]) -> Result<LabImage, JsError> {
    let name = string_arg("name", "naming the file", &name)?;
    let d = decode::decode(&name, bytes).map_err(js_error)?;
    Ok(wrap(d.grid, d.format, d.colour, d.bits, d.max_value))
}

/// An image from raw 8-bit grey bytes (row-major), e.g. the benchmark's.
#[wasm_bindgen]
pub fn image_from_u8(width: usize, height: usize, data: &[u8]) -> Result<LabImage, JsError> {
    let g = Grid::new(
        "image",
        width,
        height,
        data.iter().map(|&v| f64::from(v)).collect(),
    )
    .map_err(js_error)?;
    Ok(wrap(g, "raw", "grey", 8, 255.0))
}

/// The generated scanned frame photo with Example 4's fiducials.
#[wasm_bindgen]
pub fn scanned_frame() -> LabImage {
    wrap(sample::scanned_frame(), "generated", "grey", 8, 255.0)
}

/// The scanned frame's truth: `{ affine: [a, b, e, c, d, f], marks: [c, r]×4
/// (true), nominal: [c, r]×4, calibrated: [x, y]×4, pixel_mm }`.
#[wasm_bindgen]
pub fn scanned_frame_truth() -> Result<JsValue, JsError> {
    let flat = |v: Vec<f64>| -> JsValue { Float64Array::from(v.as_slice()).into() };
    obj(&[
        ("affine", flat(sample::TRUE_AFFINE.to_vec())),
        (
            "marks",
            flat(
                sample::true_marks()
                    .iter()
                    .flat_map(|&(c, r)| [c, r])
                    .collect(),
            ),
        ),
        (
            "nominal",
            flat(
                sample::nominal_marks()
                    .iter()
                    .flat_map(|&(c, r)| [c, r])
                    .collect(),
            ),
        ),
        (
            "calibrated",
            flat(sample::calibrated().iter().flatten().copied().collect()),
        ),
        ("pixel_mm", num(sample::PIXEL_MM)),
    ])
}

/// A filter by the `filter-window` example's kernel names, whole image.
/// For `kernel` `custom`, `custom` is the kernel's text (rows on lines or
/// separated by `;`, numbers by spaces or commas, odd sizes up to 15×15)
/// and `divisor` its divisor (`undefined`: normalised by the weights' sum);
/// both are ignored for the named kernels.
#[wasm_bindgen]
pub fn run_filter(
    img: &LabImage,
    kernel: JsValue,
    border: JsValue,
    custom: JsValue,
    divisor: Option<f64>,
) -> Result<JsValue, JsError> {
    let kernel = string_arg("kernel", "naming a kernel", &kernel)?;
    let kernel = kernel.as_str();
    let b =
        ops::border(&string_arg("border", "naming a border rule", &border)?).map_err(js_error)?;
    let custom = if custom.is_undefined() || custom.is_null() {
        None
    } else {
        Some(kernel_text(&custom)?)
    };
    let parsed = match (kernel, custom) {
        ("custom", Some(text)) => Some(ops::custom_kernel(&text, divisor).map_err(js_error)?),
        ("custom", None) => return Err(JsError::new("custom_kernel: is missing")),
        _ => None,
    };
    let l = ops::filter_image(
        &img.grid,
        kernel,
        b,
        parsed.as_ref().map(|(rows, d)| (rows.as_slice(), *d)),
    )
    .map_err(js_error)?;
    layers_js(&[l])
}

/// A custom kernel's text, whole (`string_arg` never shortens a text; only
/// ids and codes are cut short, in the example modules).
fn kernel_text(v: &JsValue) -> Result<String, JsError> {
    string_arg("custom_kernel", "of the kernel's rows", v)
}

/// A custom kernel checked as [`run_filter`] reads it: `{ rows: [[…]…],
/// divisor }`, or the error naming `custom_kernel` / `custom_divisor`.
#[wasm_bindgen]
pub fn check_custom_kernel(text: JsValue, divisor: Option<f64>) -> Result<JsValue, JsError> {
    let text = kernel_text(&text)?;
    let (rows, d) = ops::custom_kernel(&text, divisor).map_err(js_error)?;
    let a = Array::new();
    for row in &rows {
        a.push(&Float64Array::from(row.as_slice()).into());
    }
    obj(&[("rows", a.into()), ("divisor", num(d))])
}

/// Förstner's map of an image, kept in wasm memory: its `w` and `q`
/// layers once, then points for any threshold without recomputing it
/// (the lab's live threshold slider).
#[wasm_bindgen]
pub struct ForstnerMaps {
    kept: ops::ForstnerKept,
}

/// Förstner's `w`, `q` map over `size × size` windows (`interest::forstner_map`).
#[wasm_bindgen]
pub fn forstner_maps(img: &LabImage, size: usize) -> Result<ForstnerMaps, JsError> {
    Ok(ForstnerMaps {
        kept: ops::ForstnerKept::new(ops::forstner_maps(&img.grid, size).map_err(js_error)?),
    })
}

#[wasm_bindgen]
impl ForstnerMaps {
    /// The window size the map was computed with.
    pub fn size(&self) -> usize {
        self.kept.map.size
    }
    /// The `w` and `q` layers (as [`run_forstner`]'s).
    pub fn layers(&self) -> Result<JsValue, JsError> {
        layers_js(&ops::forstner_layers(&self.kept.map))
    }
    /// Seed 003's threshold and suppression on the kept map: points
    /// `[c, r, λmax(Σuv), σmax, σmin, angle]…` (as [`run_forstner`]'s);
    /// a new `threshold_px` alone re-uses the suppression
    /// (`ops::ForstnerKept`).
    pub fn points(
        &mut self,
        sigma_n: f64,
        threshold_px: f64,
        q_min: f64,
    ) -> Result<JsValue, JsError> {
        let ps = self
            .kept
            .points(sigma_n, threshold_px, q_min)
            .map_err(js_error)?;
        Ok(points_js(&ps))
    }
    /// The threshold chosen for this photo (`ops::auto_threshold`):
    /// `{ thresholdPx, wMin, share }`, or null when `w_min` is 0.
    pub fn auto_threshold(&self, sigma_n: f64) -> Result<JsValue, JsError> {
        match ops::auto_threshold(&self.kept.map, sigma_n) {
            Some(a) => obj(&[
                ("thresholdPx", a.threshold_px.into()),
                ("wMin", a.w_min.into()),
                ("share", ops::W_TOP_SHARE.into()),
            ]),
            None => Ok(JsValue::NULL),
        }
    }
}

/// Prewitt or Sobel: layers gx, gy, magnitude, direction.
#[wasm_bindgen]
pub fn run_edges(img: &LabImage, operator: JsValue, border: JsValue) -> Result<JsValue, JsError> {
    let operator = string_arg("operator", "naming an edge operator", &operator)?;
    let b =
        ops::border(&string_arg("border", "naming a border rule", &border)?).map_err(js_error)?;
    layers_js(&ops::edges(&img.grid, &operator, b).map_err(js_error)?)
}

/// Förstner: layers w, q; points `[c, r, λmax(Σuv), σmax, σmin, angle]…`.
#[wasm_bindgen]
pub fn run_forstner(
    img: &LabImage,
    size: usize,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Result<JsValue, JsError> {
    let (ls, ps) =
        ops::forstner(&img.grid, size, sigma_n, threshold_px, q_min).map_err(js_error)?;
    obj(&[("layers", layers_js(&ls)?), ("points", points_js(&ps))])
}

/// Moravec: layer of window means; points `[c, r, mean, 0, 0, 0]…`.
#[wasm_bindgen]
pub fn run_moravec(img: &LabImage, size: usize, threshold: f64) -> Result<JsValue, JsError> {
    let (l, ps) = ops::moravec(&img.grid, size, threshold).map_err(js_error)?;
    obj(&[("layers", layers_js(&[l])?), ("points", points_js(&ps))])
}

fn rect(v: &[f64], field: &str) -> Result<Rect, JsError> {
    match v {
        [c, r, w, h] if v.iter().all(|x| x.is_finite() && *x >= 0.0 && *x < 1e6) => Ok(Rect {
            c0: *c as usize,
            r0: *r as usize,
            width: *w as usize,
            height: *h as usize,
        }),
        _ => Err(JsError::new(&format!(
            "{field}: must be four non-negative numbers [c, r, width, height]"
        ))),
    }
}

/// NCC of a template box of `a` over a search box of `b`, subpixel peak and
/// LSM (`model`: `shift`, `shift-radiometric`, `affine`).
#[wasm_bindgen]
pub fn run_correlation(
    a: &LabImage,
    template: &[f64],
    b: &LabImage,
    search: &[f64],
    model: JsValue,
) -> Result<JsValue, JsError> {
    let model = string_arg("model", "naming a model", &model)?;
    let model = match model.as_str() {
        "shift" => Model::Shift,
        "shift-radiometric" => Model::ShiftRadiometric,
        "affine" => Model::AffineRadiometric,
        _ => {
            return Err(JsError::new(&format!(
                "model: must be shift, shift-radiometric or affine (got \"{}\")",
                photogrammetry_playground::read::short(&model)
            )))
        }
    };
    let t = rect(template, "template")?;
    let s = rect(search, "search")?;
    let m = ops::correlate(&a.grid, t, &b.grid, s, model).map_err(js_error)?;
    let rho: Vec<f64> = m
        .surface
        .windows
        .iter()
        .map(|w| w.rho.unwrap_or(f64::NAN))
        .collect();
    let surface = Layer {
        name: "ncc".into(),
        width: m.surface.width,
        height: m.surface.height,
        c0: s.c0 + t.width / 2,
        r0: s.r0 + t.height / 2,
        data: rho,
        signed: true,
    };
    let opt2 = |p: Option<(f64, f64)>| -> JsValue {
        p.map_or(JsValue::NULL, |(c, r)| {
            Float64Array::from(&[c, r][..]).into()
        })
    };
    let lsm = match &m.lsm {
        Some(l) => {
            let its = Array::new();
            for it in &l.iterations {
                its.push(&Float64Array::from(&it.params.a[..]).into());
            }
            let detail = match &l.status {
                Status::LeftWindow { detail } => detail.clone(),
                Status::Degenerate { reason } => reason.clone(),
                _ => String::new(),
            };
            obj(&[
                ("status", JsValue::from_str(l.status.word())),
                ("detail", JsValue::from_str(&detail)),
                ("start", Float64Array::from(&l.start.a[..]).into()),
                ("params", Float64Array::from(&l.params.a[..]).into()),
                ("iterations", its.into()),
                (
                    "window",
                    Float64Array::from(
                        &[
                            m.lsm_window.c0 as f64,
                            m.lsm_window.r0 as f64,
                            m.lsm_window.width as f64,
                            m.lsm_window.height as f64,
                        ][..],
                    )
                    .into(),
                ),
            ])?
        }
        None => JsValue::NULL,
    };
    let around = m.around.map_or(JsValue::NULL, |a| {
        Float64Array::from(a.iter().flatten().copied().collect::<Vec<_>>().as_slice()).into()
    });
    obj(&[
        ("layers", layers_js(&[surface])?),
        ("best", opt2(m.best.map(|(c, r)| (c as f64, r as f64)))),
        ("around", around),
        ("subpixel", opt2(m.subpixel)),
        ("lsm", lsm),
        // why the match is doubtful (ops::doubts): sentences, none when nothing is
        (
            "doubts",
            ops::doubts(&m)
                .iter()
                .map(|d| JsValue::from_str(d))
                .collect::<Array>()
                .into(),
        ),
    ])
}

/// Resampling with nearest, bilinear and bicubic side by side. `kind`
/// `rotate` (`params` = [angle°, scale]) or `projective` (`params` = the
/// four clicked points [c, r]×4, output `width × height`).
#[wasm_bindgen]
pub fn run_resample(
    img: &LabImage,
    kind: JsValue,
    params: &[f64],
    width: usize,
    height: usize,
) -> Result<JsValue, JsError> {
    let kind = string_arg("kind", "naming a resampling", &kind)?;
    let methods = [Method::Nearest, Method::Bilinear, Method::Bicubic];
    let map = resample_map(img, &kind, params, width, height)?;
    let grids = ops::warp(&img.grid, width, height, &map, &methods);
    let names = ["nearest", "bilinear", "bicubic"];
    let ls: Vec<Layer> = grids
        .iter()
        .zip(names)
        .map(|(g, n)| grid_layer(n, g, 0, 0, false))
        .collect();
    layers_js(&ls)
}

type PositionMap = Box<dyn Fn(f64, f64) -> (f64, f64)>;

/// The output → input map of [`run_resample`].
fn resample_map(
    img: &LabImage,
    kind: &str,
    params: &[f64],
    width: usize,
    height: usize,
) -> Result<PositionMap, JsError> {
    if width == 0 || height == 0 || width > 4096 || height > 4096 {
        return Err(JsError::new(
            "width: the output must be 1 to 4096 pixels across and down",
        ));
    }
    if params.iter().any(|p| !p.is_finite()) {
        return Err(JsError::new("params: must be finite numbers"));
    }
    match kind {
        "rotate" => {
            let [angle, scale] = params else {
                return Err(JsError::new(
                    "params: rotate takes [angle in degrees, scale]",
                ));
            };
            let map = ops::rotate_scale(&img.grid, *angle, *scale).map_err(js_error)?;
            Ok(Box::new(map))
        }
        "projective" => {
            if params.len() != 8 {
                return Err(JsError::new(
                    "params: projective takes four points [c, r]×4",
                ));
            }
            let pts: Vec<(f64, f64)> = params.chunks(2).map(|p| (p[0], p[1])).collect();
            let t = ops::projective(&pts, width, height).map_err(js_error)?;
            Ok(Box::new(move |x: f64, y: f64| {
                t.apply(x, y).unwrap_or((f64::NAN, f64::NAN))
            }))
        }
        _ => Err(JsError::new(&format!(
            "kind: must be rotate or projective (got \"{}\")",
            photogrammetry_playground::read::short(kind)
        ))),
    }
}

/// Where output pixel `(c, r)` of [`run_resample`] reads the input: `[x, y]`.
#[wasm_bindgen]
pub fn resample_position(
    img: &LabImage,
    kind: JsValue,
    params: &[f64],
    width: usize,
    height: usize,
    c: usize,
    r: usize,
) -> Result<Float64Array, JsError> {
    let kind = string_arg("kind", "naming a resampling", &kind)?;
    let map = resample_map(img, &kind, params, width, height)?;
    let (x, y) = map(c as f64, r as f64);
    Ok(Float64Array::from(&[x, y][..]))
}

/// Threshold, the region at `(c, r)`, its boundary, chain code, length and
/// shape.
#[wasm_bindgen]
pub fn run_boundary(
    img: &LabImage,
    threshold: f64,
    c: usize,
    r: usize,
) -> Result<JsValue, JsError> {
    let t = ops::boundary(&img.grid, threshold, c, r).map_err(js_error)?;
    let pixels: Vec<f64> = t
        .boundary
        .pixels
        .iter()
        .flat_map(|p| [p[0] as f64, p[1] as f64])
        .collect();
    let shape = match &t.shape {
        Some(s) => obj(&[
            ("diameter", num(s.diameter)),
            ("minor_axis_length", num(s.minor_axis_length)),
            ("eccentricity", s.eccentricity.map_or(JsValue::NULL, num)),
        ])?,
        None => JsValue::NULL,
    };
    obj(&[
        (
            "layers",
            layers_js(&[grid_layer("region", &t.mask, 0, 0, false)])?,
        ),
        ("pixels", Float64Array::from(pixels.as_slice()).into()),
        (
            "code",
            JsValue::from_str(
                &t.boundary
                    .code
                    .iter()
                    .map(|d| d.to_string())
                    .collect::<String>(),
            ),
        ),
        ("area", num(t.boundary.area as f64)),
        ("length", num(t.length.length)),
        ("horizontal", num(t.length.horizontal as f64)),
        ("vertical", num(t.length.vertical as f64)),
        ("diagonal", num(t.length.diagonal as f64)),
        ("shape", shape),
    ])
}

/// Measures the four fiducials near `approx` ([c, r]×4) with a template of
/// the mark, then fits Example 4's similarity and affine transformations.
#[wasm_bindgen]
pub fn run_fiducials(img: &LabImage, approx: &[f64]) -> Result<JsValue, JsError> {
    if approx.len() != 8 || approx.iter().any(|v| !v.is_finite()) {
        return Err(JsError::new(
            "marks: need four approximate positions [c, r]×4",
        ));
    }
    let pts: Vec<(f64, f64)> = approx.chunks(2).map(|p| (p[0], p[1])).collect();
    let template = sample::mark_template(21).map_err(js_error)?;
    let marks = ops::measure_marks(&img.grid, &template, &pts, 12).map_err(js_error)?;
    let measured: Vec<(f64, f64)> = marks.iter().map(|m| m.measured).collect();
    let (sim, aff) = ops::fit_fiducials(&measured, &sample::calibrated()).map_err(js_error)?;
    let fit_js = |f: &photogrammetry_playground::transform::Fit| -> Result<JsValue, JsError> {
        obj(&[
            (
                "params",
                Float64Array::from(f.transform.params.as_slice()).into(),
            ),
            (
                "residuals",
                Float64Array::from(
                    f.point_residuals
                        .iter()
                        .flatten()
                        .copied()
                        .collect::<Vec<_>>()
                        .as_slice(),
                )
                .into(),
            ),
            ("sigma0", f.adjustment.sigma0.map_or(JsValue::NULL, num)),
        ])
    };
    let flat: Vec<f64> = marks
        .iter()
        .flat_map(|m| [m.measured.0, m.measured.1, m.ncc, m.iterations as f64])
        .collect();
    obj(&[
        ("marks", Float64Array::from(flat.as_slice()).into()),
        ("similarity", fit_js(&sim)?),
        ("affine", fit_js(&aff)?),
    ])
}

/// Refines one fiducial the student clicked at `(c, r)`: the mark's template
/// matched by NCC within ±12 pixels, its subpixel peak, then LSM (shift +
/// radiometric), as [`run_fiducials`] measures each mark. Returns `[c, r,
/// ρ, LSM iterations]` (iterations 0: the subpixel peak, LSM did not
/// converge).
#[wasm_bindgen]
pub fn refine_mark(img: &LabImage, c: f64, r: f64) -> Result<Float64Array, JsError> {
    let (w, h) = (img.grid.width() as f64, img.grid.height() as f64);
    if !(c.is_finite() && r.is_finite() && c >= 0.0 && r >= 0.0 && c < w && r < h) {
        return Err(JsError::new("mark: the click must lie inside the image"));
    }
    let template = sample::mark_template(21).map_err(js_error)?;
    let marks = ops::measure_marks(&img.grid, &template, &[(c, r)], 12).map_err(js_error)?;
    let m = marks
        .first()
        .ok_or_else(|| JsError::new("mark: could not be measured"))?;
    Ok(Float64Array::from(
        &[m.measured.0, m.measured.1, m.ncc, m.iterations as f64][..],
    ))
}

/// Example 4's similarity and affine transformations fitted to four
/// measured marks `[c, r]×4` (the student's), against the calibrated
/// positions: `{ similarity, affine }`, each `{ params, residuals: [vx,
/// vy]×4 (mm), sigma0 }`.
#[wasm_bindgen]
pub fn fit_fiducial_marks(measured: &[f64]) -> Result<JsValue, JsError> {
    if measured.len() != 8 || measured.iter().any(|v| !v.is_finite()) {
        return Err(JsError::new("marks: need four measured positions [c, r]×4"));
    }
    let pts: Vec<(f64, f64)> = measured.chunks(2).map(|p| (p[0], p[1])).collect();
    let (sim, aff) = ops::fit_fiducials(&pts, &sample::calibrated()).map_err(js_error)?;
    obj(&[("similarity", fit_js(&sim)?), ("affine", fit_js(&aff)?)])
}

fn fit_js(f: &photogrammetry_playground::transform::Fit) -> Result<JsValue, JsError> {
    let residuals: Vec<f64> = f.point_residuals.iter().flatten().copied().collect();
    obj(&[
        (
            "params",
            Float64Array::from(f.transform.params.as_slice()).into(),
        ),
        ("residuals", Float64Array::from(residuals.as_slice()).into()),
        ("sigma0", f.adjustment.sigma0.map_or(JsValue::NULL, num)),
    ])
}

/// Traps the wasm instance on purpose (a wasm `unreachable` instruction),
/// so that the recovery from a trapped instance can be tested
/// (`lab/tests/web_lab.rs`). Only in builds with the `test-hooks` feature
/// (the tests' builds turn it on): the page's module has no such export.
#[cfg(feature = "test-hooks")]
#[wasm_bindgen]
pub fn trap_for_tests() {
    core::arch::wasm32::unreachable()
}

// The fast 8-bit exports that `npm run bench -- ops` times: only in builds
// with the `bench` feature (scripts/bench-ops/run.sh and the tests' builds).
#[cfg(feature = "bench")]
mod fast;
#[cfg(feature = "bench")]
pub use fast::FastImage;
