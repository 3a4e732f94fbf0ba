//! The operators' exports: each `run_*` reads its parameters (every
//! error names its field), calls [`crate::ops`] on the image's grid and
//! its cached bytes ([`image`]), and returns plain objects whose layers
//! are `Float32Array`s. [`op_halo`] and [`exact_at`] take an operator by
//! the worker's request name with the request's own arguments object.

use super::*;
use js_sys::Float32Array;
use wasm_bindgen::JsCast;

/// The image as the operators take it: its bytes when it is 8-bit (found
/// once per image), and its grid — for an image made from bytes only if an
/// operator's reference path asks for it (`ops::Image::grid`).
fn image(img: &LabImage) -> ops::Image<'_> {
    match (img.grid.get(), img.bytes()) {
        (Some(grid), None) => ops::Image::with_bytes(grid, None).with_levels(&img.levels),
        (Some(grid), bytes) => ops::Image::with_bytes(grid, bytes),
        (None, Some(bytes)) => ops::Image::from_bytes(img.width, img.height, bytes)
            .unwrap_or_else(|_| ops::Image::from(img.grid())),
        (None, None) => ops::Image::from_levels(img.width, img.height, &img.levels)
            .unwrap_or_else(|_| ops::Image::from(img.grid())),
    }
}

thread_local! {
    /// Buffers the page gave back for the next layers ([`spare_buffers`]).
    static SPARE: std::cell::RefCell<Vec<js_sys::ArrayBuffer>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Keeps `buffers` (`ArrayBuffer`s the page is done with: the last bands'
/// layers, tiles.js) for the layers of the next `run_*` calls, which then
/// copy their values into one of them instead of a fresh buffer (a fresh
/// one costs its pages first: as much again as the copy). Returns the
/// buffers kept before that were not used, to be handed back (the page's
/// own count stays bounded).
#[wasm_bindgen]
pub fn spare_buffers(buffers: Array) -> Array {
    let out = Array::new();
    SPARE.with(|s| {
        let mut s = s.borrow_mut();
        for b in s.drain(..) {
            out.push(&b);
        }
        s.extend(buffers.iter().filter_map(|b| b.dyn_into().ok()));
    });
    out
}

/// `data` as a `Float32Array` out of wasm memory (one copy), into a spare
/// buffer that is large enough when the page gave one.
fn f32_array(data: &[f32]) -> Float32Array {
    let n = data.len();
    let spare = SPARE.with(|s| {
        let mut s = s.borrow_mut();
        let i = s.iter().position(|b| b.byte_length() as usize >= n * 4)?;
        Some(s.swap_remove(i))
    });
    let a = match spare {
        Some(b) => Float32Array::new_with_byte_offset_and_length(&b, 0, n as u32),
        None => Float32Array::new_with_length(n as u32),
    };
    a.copy_from(data);
    a
}

/// [`image`] with its grid (built once and kept with the image when it was
/// made from bytes): for the operators that read grey values from the grid
/// (correlation's windows, the boundary's region, the fiducials), and the
/// levels kept with it (a colour photo's: found once, not per call).
fn whole_image(img: &LabImage) -> ops::Image<'_> {
    ops::Image::with_bytes(img.grid(), img.bytes()).with_levels(&img.levels)
}

fn layer_js(l: &Layer) -> Result<JsValue, JsError> {
    obj(&[
        ("name", JsValue::from_str(&l.name)),
        ("width", num(l.width as f64)),
        ("height", num(l.height as f64)),
        ("c0", num(l.c0 as f64)),
        ("r0", num(l.r0 as f64)),
        ("signed", JsValue::from_bool(l.signed)),
        ("data", f32_array(&l.data).into()),
    ])
}

fn layers_js(ls: &[Layer]) -> Result<JsValue, JsError> {
    let a = Array::new();
    for l in ls {
        a.push(&layer_js(l)?);
    }
    Ok(a.into())
}

fn points_js(ps: &[Point]) -> JsValue {
    let flat: Vec<f64> = ps
        .iter()
        .flat_map(|p| [p.c as f64, p.r as f64, p.score, p.major, p.minor, p.angle])
        .collect();
    Float64Array::from(flat.as_slice()).into()
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
        image(img),
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
        kept: ops::ForstnerKept::new(image(img), size).map_err(js_error)?,
    })
}

#[wasm_bindgen]
impl ForstnerMaps {
    /// The window size the map was computed with.
    pub fn size(&self) -> usize {
        self.kept.size()
    }
    /// The `w` and `q` layers (as [`run_forstner`]'s).
    pub fn layers(&self) -> Result<JsValue, JsError> {
        layers_js(self.kept.layers())
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
        match self.kept.auto_threshold(sigma_n) {
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
    layers_js(&ops::edges(image(img), &operator, b).map_err(js_error)?)
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
        ops::forstner(image(img), size, sigma_n, threshold_px, q_min).map_err(js_error)?;
    obj(&[("layers", layers_js(&ls)?), ("points", points_js(&ps))])
}

/// Moravec: layer of window means; points `[c, r, mean, 0, 0, 0]…`.
#[wasm_bindgen]
pub fn run_moravec(img: &LabImage, size: usize, threshold: f64) -> Result<JsValue, JsError> {
    let (l, ps) = ops::moravec(image(img), size, threshold).map_err(js_error)?;
    obj(&[("layers", layers_js(&[l])?), ("points", points_js(&ps))])
}

pub(super) fn rect(v: &[f64], field: &str) -> Result<Rect, JsError> {
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
    let m = ops::correlate(whole_image(a), t, whole_image(b), s, model).map_err(js_error)?;
    let surface = Layer {
        name: "ncc".into(),
        width: m.surface.width,
        height: m.surface.height,
        c0: s.c0 + t.width / 2,
        r0: s.r0 + t.height / 2,
        data: m.surface.rho.clone(),
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
/// four clicked points [c, r]×4, output `width × height`). `row0`, `row1`
/// (optional): only the output rows `row0 … row1 − 1` (a band; the
/// layers' `r0` is `row0`), over the whole input.
#[wasm_bindgen]
pub fn run_resample(
    img: &LabImage,
    kind: JsValue,
    params: &[f64],
    width: usize,
    height: usize,
    row0: Option<usize>,
    row1: Option<usize>,
) -> Result<JsValue, JsError> {
    let kind = string_arg("kind", "naming a resampling", &kind)?;
    let warp = warp_of(img, &kind, params, width, height)?;
    let rows = row0.unwrap_or(0)..row1.unwrap_or(height);
    if rows.start >= rows.end || rows.end > height {
        return Err(JsError::new(&format!(
            "row0: the band's rows must lie within the {height} output rows, first before last"
        )));
    }
    layers_js(&ops::resample(image(img), &warp, rows).map_err(js_error)?)
}

/// The output → input map of [`run_resample`].
fn warp_of(
    img: &LabImage,
    kind: &str,
    params: &[f64],
    width: usize,
    height: usize,
) -> Result<ops::Warp, JsError> {
    let size = (img.width, img.height);
    ops::Warp::new(size, kind, params, width, height).map_err(js_error)
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
    let (x, y) = warp_of(img, &kind, params, width, height)?.position(c as f64, r as f64);
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
    let t = ops::boundary(whole_image(img), threshold, c, r).map_err(js_error)?;
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
        ("layers", layers_js(&[t.region])?),
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
    let marks = ops::measure_marks(whole_image(img), &template, &pts, 12).map_err(js_error)?;
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
    let (w, h) = (img.width as f64, img.height as f64);
    if !(c.is_finite() && r.is_finite() && c >= 0.0 && r >= 0.0 && c < w && r < h) {
        return Err(JsError::new("mark: the click must lie inside the image"));
    }
    let template = sample::mark_template(21).map_err(js_error)?;
    let marks = ops::measure_marks(whole_image(img), &template, &[(c, r)], 12).map_err(js_error)?;
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

/// `args[key]` (undefined when `args` is not an object).
fn field(args: &JsValue, key: &str) -> JsValue {
    if args.is_object() {
        Reflect::get(args, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
    } else {
        JsValue::UNDEFINED
    }
}

/// A whole number `args[key]` in `0 … max`.
fn whole_arg(args: &JsValue, key: &str, max: f64) -> Result<usize, JsError> {
    match field(args, key).as_f64() {
        Some(v) if v.fract() == 0.0 && (0.0..=max).contains(&v) => Ok(v as usize),
        _ => Err(JsError::new(&format!(
            "{key}: must be a whole number from 0 to {max}"
        ))),
    }
}

/// Numbers `args[key]` (an array).
fn numbers_arg(args: &JsValue, key: &str) -> Result<Vec<f64>, JsError> {
    let v = field(args, key);
    if !Array::is_array(&v) && !v.is_instance_of::<Float64Array>() {
        return Err(JsError::new(&format!("{key}: must be a list of numbers")));
    }
    let out: Vec<f64> = Array::from(&v)
        .iter()
        .map(|x| x.as_f64().unwrap_or(f64::NAN))
        .collect();
    if out.len() > 64 || out.iter().any(|x| !x.is_finite()) {
        return Err(JsError::new(&format!(
            "{key}: must be a list of finite numbers"
        )));
    }
    Ok(out)
}

fn str_arg(args: &JsValue, key: &'static str, what: &'static str) -> Result<String, JsError> {
    string_arg(key, what, &field(args, key))
}

/// An operator by the worker's request name (`filter`, `edges`,
/// `forstner` / `forstnerMaps`, `moravec`, `resample`, `correlation`) with
/// that request's arguments object.
fn op_of(op: &JsValue, args: &JsValue) -> Result<ops::Op, JsError> {
    let name = string_arg("op", "naming an operator", op)?;
    let border = |args: &JsValue| -> Result<_, JsError> {
        ops::border(&str_arg(args, "border", "naming a border rule")?).map_err(js_error)
    };
    Ok(match name.as_str() {
        "filter" => {
            let kernel = str_arg(args, "kernel", "naming a kernel")?;
            let custom = if kernel == "custom" {
                let text = kernel_text(&field(args, "custom"))?;
                let divisor = field(args, "divisor").as_f64();
                Some(ops::custom_kernel(&text, divisor).map_err(js_error)?)
            } else {
                None
            };
            ops::Op::Filter {
                kernel,
                border: border(args)?,
                custom,
            }
        }
        "edges" => ops::Op::Edges {
            operator: str_arg(args, "operator", "naming an edge operator")?,
            border: border(args)?,
        },
        "forstner" | "forstnerMaps" => ops::Op::Forstner {
            size: whole_arg(args, "size", 1e6)?,
        },
        "moravec" => ops::Op::Moravec {
            size: whole_arg(args, "size", 1e6)?,
        },
        "resample" => ops::Op::Resample {
            kind: str_arg(args, "kind", "naming a resampling")?,
            params: numbers_arg(args, "params")?,
            width: whole_arg(args, "width", 1e6)?,
            height: whole_arg(args, "height", 1e6)?,
        },
        "correlation" => ops::Op::Correlation {
            template: rect(&numbers_arg(args, "template")?, "template")?,
            search: rect(&numbers_arg(args, "search")?, "search")?,
        },
        _ => {
            let known = "filter, edges, forstner, moravec, resample or correlation";
            let got = photogrammetry_playground::read::short(&name);
            return Err(JsError::new(&format!(
                "op: must be {known} (got \"{got}\")"
            )));
        }
    })
}

/// Rows of real neighbours a band needs above and below so that its own
/// rows of every layer (and its points) equal the whole image's
/// (`ops::halo`): `op` and `args` as the worker's request (`"filter"`,
/// `{ kernel, border, custom, divisor }`; `"forstner"`, `{ size }` …);
/// `undefined` for operators that do not run by bands of input rows
/// (`resample` bands its output rows: `run_resample`'s `row0`, `row1`).
#[wasm_bindgen]
pub fn op_halo(op: JsValue, args: JsValue) -> Result<Option<usize>, JsError> {
    ops::halo(&op_of(&op, &args)?).map_err(js_error)
}

/// The exact value of layer `layer` of `op` (with the request's `args`)
/// at pixel `(c, r)`: the reference function on that pixel's window, the
/// worked example's number (`ops::exact_at`); `undefined` where the layer
/// has none. `b`: the search image of a correlation (else unused).
#[wasm_bindgen]
pub fn exact_at(
    a: &LabImage,
    b: &LabImage,
    op: JsValue,
    args: JsValue,
    layer: JsValue,
    c: usize,
    r: usize,
) -> Result<Option<f64>, JsError> {
    let op = op_of(&op, &args)?;
    let layer = string_arg("layer", "naming a layer", &layer)?;
    ops::exact_at(a.grid(), b.grid(), &op, &layer, c, r).map_err(js_error)
}
