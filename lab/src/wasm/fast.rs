//! Fast 8-bit operators (issue 15): an image kept in wasm memory with its
//! output buffers, allocated once and reused call after call, so that a
//! slider drag re-runs an operator without copying. Each method calls one
//! core fast path (`filter::fast`, `interest::fast`, `correlation::fast`,
//! `resample::fast`, `chain::fast`); outputs are read through `out_f32` /
//! `out_u8` (copies) or viewed in place with `out_ptr` / `out_len` over
//! the module's memory. `npm run bench -- ops` times these same exports.

use super::*;

use js_sys::Float32Array;

use photogrammetry_playground::chain::fast as chain_fast;
use photogrammetry_playground::correlation::fast as zncc_fast;
use photogrammetry_playground::filter::fast as filter_fast;
use photogrammetry_playground::interest::fast as interest_fast;
use photogrammetry_playground::raster::Gray;
use photogrammetry_playground::resample::fast as warp_fast;
use photogrammetry_playground::resample::Method;

use super::run::rect;

/// An 8-bit grey image and the buffers of the fast operators' outputs.
#[wasm_bindgen]
pub struct FastImage {
    width: usize,
    height: usize,
    data: Vec<u8>,
    /// Float outputs (up to three: gx, gy, magnitude / w, q / …).
    f32_out: [Vec<f32>; 3],
    /// The byte output (median).
    u8_out: Vec<u8>,
    /// The borders of the last `contours` call.
    borders: Vec<chain_fast::Contour>,
}

fn resize_f32(v: &mut Vec<f32>, n: usize) {
    if v.len() != n {
        *v = vec![0.0; n];
    }
}

#[wasm_bindgen]
impl FastImage {
    /// `width × height` bytes, row-major.
    #[wasm_bindgen(constructor)]
    pub fn new(width: usize, height: usize, data: &[u8]) -> Result<FastImage, JsError> {
        Gray::new("image", data, width, height).map_err(js_error)?;
        Ok(FastImage {
            width,
            height,
            data: data.to_vec(),
            f32_out: [Vec::new(), Vec::new(), Vec::new()],
            u8_out: Vec::new(),
            borders: Vec::new(),
        })
    }

    fn gray(&self) -> Result<Gray<'_>, JsError> {
        Gray::new("image", &self.data, self.width, self.height).map_err(js_error)
    }

    fn outputs(&mut self, k: usize, n: usize) {
        for v in self.f32_out.iter_mut().take(k) {
            resize_f32(v, n);
        }
    }

    /// 3×3 mean → output 0.
    pub fn mean3(&mut self, border: JsValue) -> Result<(), JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        let n = self.width * self.height;
        self.outputs(1, n);
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        filter_fast::mean3(img, b, &mut self.f32_out[0]).map_err(js_error)
    }

    /// Separable Gaussian, taps `exp(−i²/2σ²)` normalised, `i = −radius … radius` → output 0.
    pub fn gaussian(&mut self, sigma: f64, radius: usize, border: JsValue) -> Result<(), JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        let taps: Vec<f32> = filter_fast::gaussian_taps(sigma, radius)
            .ok_or_else(|| JsError::new("sigma: must be a number greater than 0"))?
            .iter()
            .map(|&v| v as f32)
            .collect();
        self.outputs(1, self.width * self.height);
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        filter_fast::separable(img, &taps, &taps, 1.0, b, &mut self.f32_out[0]).map_err(js_error)
    }

    /// Sobel gx, gy, magnitude → outputs 0, 1, 2.
    pub fn sobel(&mut self, border: JsValue) -> Result<(), JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        self.outputs(3, self.width * self.height);
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        let [gx, gy, mag] = &mut self.f32_out;
        filter_fast::sobel(img, b, gx, gy, mag).map_err(js_error)
    }

    /// Förstner w, q over `size × size` gradient windows → outputs 0, 1.
    pub fn forstner(&mut self, size: usize) -> Result<(), JsError> {
        self.outputs(2, self.width * self.height);
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        let [w, q, _] = &mut self.f32_out;
        interest_fast::forstner_wq(img, size, w, q).map_err(js_error)
    }

    /// ZNCC of the template box `[c, r, w, h]` over the search box (both of
    /// this image) → output 0 (`(sw−tw+1) × (sh−th+1)`); returns
    /// `[c, r, ρ]` of the best position (top-left, in the search box) or
    /// an empty array.
    pub fn zncc(&mut self, template: &[f64], search: &[f64]) -> Result<Vec<f64>, JsError> {
        let t = rect(template, "template")?;
        let s = rect(search, "search")?;
        let img = self.gray()?;
        let g = img.to_grid();
        let cut = |r: Rect, f: &str| -> Result<Vec<u8>, JsError> {
            g.window(r.c0, r.r0, r.width, r.height)
                .and_then(|w| w.to_u8())
                .ok_or_else(|| JsError::new(&format!("{f}: the box does not lie inside the image")))
        };
        let (tb, sb) = (cut(t, "template")?, cut(s, "search")?);
        let tg = Gray::new("template", &tb, t.width, t.height).map_err(js_error)?;
        let sg = Gray::new("search", &sb, s.width, s.height).map_err(js_error)?;
        let n = (s.width + 1).saturating_sub(t.width) * (s.height + 1).saturating_sub(t.height);
        self.outputs(1, n);
        let peak = zncc_fast::zncc(sg, tg, &mut self.f32_out[0]).map_err(js_error)?;
        Ok(peak.map_or(Vec::new(), |p| {
            vec![p.c as f64, p.r as f64, f64::from(p.rho)]
        }))
    }

    /// ZNCC on prepared byte buffers (search `sw × sh`, template `tw × th`)
    /// → output 0; the timed part of the benchmark's T4.
    pub fn zncc_bytes(
        &mut self,
        search: &[u8],
        sw: usize,
        sh: usize,
        template: &[u8],
        tw: usize,
        th: usize,
    ) -> Result<Vec<f64>, JsError> {
        let sg = Gray::new("search", search, sw, sh).map_err(js_error)?;
        let tg = Gray::new("template", template, tw, th).map_err(js_error)?;
        let n = (sw + 1).saturating_sub(tw) * (sh + 1).saturating_sub(th);
        self.outputs(1, n);
        let peak = zncc_fast::zncc(sg, tg, &mut self.f32_out[0]).map_err(js_error)?;
        Ok(peak.map_or(Vec::new(), |p| {
            vec![p.c as f64, p.r as f64, f64::from(p.rho)]
        }))
    }

    /// Affine warp, output → input map `[m00, m01, m02, m10, m11, m12]`,
    /// `method` nearest / bilinear / bicubic (kernel parameter `a`), fill 0,
    /// same size → output 0.
    pub fn warp_affine(&mut self, m: &[f64], method: JsValue, a: f64) -> Result<(), JsError> {
        let method = string_arg("method", "naming an interpolation", &method)?;
        let [m00, m01, m02, m10, m11, m12] = m else {
            return Err(JsError::new("map: needs 6 numbers"));
        };
        let map = [[*m00, *m01, *m02], [*m10, *m11, *m12]];
        let method = match method.as_str() {
            "nearest" => Method::Nearest,
            "bilinear" => Method::Bilinear,
            "bicubic" => Method::Bicubic,
            _ => return Err(JsError::new("method: must be nearest, bilinear or bicubic")),
        };
        let (w, h) = (self.width, self.height);
        self.outputs(1, w * h);
        let img = Gray::new("image", &self.data, w, h).map_err(js_error)?;
        warp_fast::warp_affine(img, &map, method, a, 0.0, (w, h), &mut self.f32_out[0])
            .map_err(js_error)
    }

    /// 3×3 median → the byte output.
    pub fn median3(&mut self, border: JsValue) -> Result<(), JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        let n = self.width * self.height;
        if self.u8_out.len() != n {
            self.u8_out = vec![0; n];
        }
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        filter_fast::median3(img, b, &mut self.u8_out).map_err(js_error)
    }

    /// Every border (outer and hole) of the non-zero pixels, Suzuki–Abe
    /// (`findContours` RETR_LIST, CHAIN_APPROX_NONE); returns
    /// `[number of borders, number of points]`; the points, `c, r, …` per
    /// border, through [`FastImage::contour`].
    pub fn contours(&mut self) -> Result<Vec<f64>, JsError> {
        let img = Gray::new("image", &self.data, self.width, self.height).map_err(js_error)?;
        self.borders = chain_fast::contours(img).map_err(js_error)?;
        let points: usize = self.borders.iter().map(|c| c.points.len()).sum();
        Ok(vec![self.borders.len() as f64, points as f64])
    }

    /// Border `i` of the last [`FastImage::contours`]: `c, r, c, r, …`
    /// (empty past the last one).
    pub fn contour(&self, i: usize) -> Vec<u32> {
        self.borders.get(i).map_or(Vec::new(), |c| {
            c.points.iter().flat_map(|&(x, y)| [x, y]).collect()
        })
    }

    /// Whether border `i` is a hole's.
    pub fn contour_is_hole(&self, i: usize) -> bool {
        self.borders.get(i).is_some_and(|c| c.hole)
    }

    /// A copy of float output `i`.
    pub fn out_f32(&self, i: usize) -> Float32Array {
        Float32Array::from(self.f32_out.get(i).map_or(&[][..], |v| &v[..]))
    }

    /// A copy of the byte output.
    pub fn out_u8(&self) -> js_sys::Uint8Array {
        js_sys::Uint8Array::from(&self.u8_out[..])
    }

    /// Where float output `i` (or, for `i = 3`, the byte output) starts in
    /// the module's memory, for a view without a copy.
    pub fn out_ptr(&self, i: usize) -> usize {
        match self.f32_out.get(i) {
            Some(v) => v.as_ptr() as usize,
            None => self.u8_out.as_ptr() as usize,
        }
    }

    /// Number of values of output `i` (`i = 3`: the byte output).
    pub fn out_len(&self, i: usize) -> usize {
        self.f32_out.get(i).map_or(self.u8_out.len(), Vec::len)
    }
}
