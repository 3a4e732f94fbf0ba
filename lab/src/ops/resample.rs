//! Resampling: rotation and scaling about the image centre, or the
//! projective rectification of four clicked points; nearest neighbour,
//! bilinear and bicubic side by side.
//!
//! On an 8-bit image by the core's `resample::fast`: the rotation as an
//! affine map with the interior runs of `warp_affine_with` (positions on
//! the run from the affine form, those of every checked pixel — the edges
//! of the runs, and every nearest-neighbour pixel — from the reference's
//! own expression, so where a value exists and which pixel is nearest are
//! the reference's decisions), the projective map pixel by pixel through
//! its homography (`warp_map`). A colour photo's levels (`ops::Levels`)
//! take the same functions through `resample::fast::Levels`: interpolated
//! in `f64` on the whole numbers `n`, divided by the scale once. Otherwise
//! `resample::warp`.

use super::*;
use photogrammetry_playground::resample::{self as rs, fast as rfast, Method};
use photogrammetry_playground::transform::{self, PointPair};

/// Resampling by a transformation of output pixel → input position
/// (`resample::warp`), one grid per method: the reference.
pub fn warp(
    img: &Grid,
    width: usize,
    height: usize,
    map: &dyn Fn(f64, f64) -> (f64, f64),
    methods: &[Method],
) -> Vec<Grid> {
    methods
        .iter()
        .map(|&m| rs::warp(img, width, height, map, m, 0.0))
        .collect()
}

/// Rotation by `angle_deg` (clockwise on the screen) and scaling by
/// `scale` about the image centre: the output → input map.
pub fn rotate_scale(
    img: &Grid,
    angle_deg: f64,
    scale: f64,
) -> Result<impl Fn(f64, f64) -> (f64, f64)> {
    let rot = Rotation::new(img.width(), img.height(), angle_deg, scale)?;
    Ok(move |x, y| rot.at(x, y))
}

/// [`rotate_scale`]'s map for a `w × h` image.
#[derive(Debug, Clone, Copy)]
struct Rotation {
    mc: f64,
    mr: f64,
    sin: f64,
    cos: f64,
    scale: f64,
}

impl Rotation {
    fn new(w: usize, h: usize, angle_deg: f64, scale: f64) -> Result<Self> {
        if !(scale.is_finite() && scale > 0.0 && angle_deg.is_finite()) {
            return Err(Error::input("scale", "must be a number greater than 0"));
        }
        let (sin, cos) = angle_deg.to_radians().sin_cos();
        Ok(Rotation {
            mc: (w as f64 - 1.0) / 2.0,
            mr: (h as f64 - 1.0) / 2.0,
            sin,
            cos,
            scale,
        })
    }

    /// The input position of output pixel `(x, y)`: the inverse of
    /// "rotate by θ then scale" (rotate by −θ, divide by the scale).
    fn at(&self, x: f64, y: f64) -> (f64, f64) {
        let (dx, dy) = (x - self.mc, y - self.mr);
        (
            (self.cos * dx + self.sin * dy) / self.scale + self.mc,
            (-self.sin * dx + self.cos * dy) / self.scale + self.mr,
        )
    }

    /// The same map as an affine `[[m00, m01, m02], [m10, m11, m12]]`.
    fn affine(&self) -> rfast::Affine {
        let (a, b) = (self.cos / self.scale, self.sin / self.scale);
        let (mc, mr) = (self.mc, self.mr);
        [[a, b, mc - a * mc - b * mr], [-b, a, mr + b * mc - a * mr]]
    }
}

/// The projective rectification of four clicked points onto a rectangle
/// `width × height`: the 004 table's projective model fitted through
/// `transform::fit` from output corners to the clicked input positions.
pub fn projective(
    clicked: &[(f64, f64)],
    width: usize,
    height: usize,
) -> Result<transform::Transform> {
    if clicked.len() != 4 {
        return Err(Error::input(
            "points",
            format!("needs 4 clicked points, got {}", clicked.len()),
        ));
    }
    let (w, h) = (width as f64 - 1.0, height as f64 - 1.0);
    let corners = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)];
    let pairs: Vec<PointPair> = corners
        .iter()
        .zip(clicked)
        .map(|(&(u, v), &(x, y))| PointPair { u, v, x, y })
        .collect();
    Ok(transform::fit(transform::Model::Projective, &pairs)
        .map_err(|e| e.in_field("points"))?
        .transform)
}

/// Largest output side of a resampling.
pub const MAX_WARP_SIDE: usize = 4096;

/// An output → input position map.
type PositionMap = Box<dyn Fn(f64, f64) -> (f64, f64)>;

/// A resampling as the lab's menu gives it: `kind` `rotate` (`params` =
/// [angle°, scale]) or `projective` (`params` = the four clicked points
/// [c, r]×4), output `width × height`, for an input of `in_w × in_h`.
pub struct Warp {
    map: PositionMap,
    affine: Option<rfast::Affine>,
    pub width: usize,
    pub height: usize,
}

impl Warp {
    pub fn new(
        (in_w, in_h): (usize, usize),
        kind: &str,
        params: &[f64],
        width: usize,
        height: usize,
    ) -> Result<Warp> {
        if width == 0 || height == 0 || width > MAX_WARP_SIDE || height > MAX_WARP_SIDE {
            return Err(Error::input(
                "width",
                format!("the output must be 1 to {MAX_WARP_SIDE} pixels across and down"),
            ));
        }
        if params.iter().any(|p| !p.is_finite()) {
            return Err(Error::input("params", "must be finite numbers"));
        }
        let (map, affine): (PositionMap, _) = match kind {
            "rotate" => {
                let [angle, scale] = params else {
                    return Err(Error::input(
                        "params",
                        "rotate takes [angle in degrees, scale]",
                    ));
                };
                let rot = Rotation::new(in_w, in_h, *angle, *scale)?;
                (Box::new(move |x, y| rot.at(x, y)), Some(rot.affine()))
            }
            "projective" => {
                if params.len() != 8 {
                    return Err(Error::input(
                        "params",
                        "projective takes four points [c, r]×4",
                    ));
                }
                let pts: Vec<(f64, f64)> = params.chunks(2).map(|p| (p[0], p[1])).collect();
                let t = projective(&pts, width, height)?;
                let map = move |x: f64, y: f64| t.apply(x, y).unwrap_or((f64::NAN, f64::NAN));
                (Box::new(map), None)
            }
            _ => {
                return Err(Error::input(
                    "kind",
                    format!("must be rotate or projective (got \"{}\")", short(kind)),
                ))
            }
        };
        Ok(Warp {
            map,
            affine,
            width,
            height,
        })
    }

    /// Where output pixel `(c, r)` reads the input (the reference's map).
    pub fn position(&self, c: f64, r: f64) -> (f64, f64) {
        (self.map)(c, r)
    }
}

/// The three methods of the resampling family, in the menu's order.
pub const METHODS: [(Method, &str); 3] = [
    (Method::Nearest, "nearest"),
    (Method::Bilinear, "bilinear"),
    (Method::Bicubic, "bicubic"),
];

/// Output rows `rows` (a band of the `warp.height` rows; all of them for
/// the whole image) of each method, as layers whose `r0` is the band's
/// first row. 0 where the method has no value (outside the input or too
/// near its edge), as `resample::warp` fills.
pub fn resample<'a>(
    img: impl Into<Image<'a>>,
    warp: &Warp,
    rows: std::ops::Range<usize>,
) -> Result<Vec<Layer>> {
    let img = img.into();
    let (r0, r1) = (rows.start.min(warp.height), rows.end.min(warp.height));
    let band = Region {
        c0: 0,
        r0,
        width: warp.width,
        height: r1.saturating_sub(r0),
    };
    let shifted = |x: f64, y: f64| warp.position(x, y + r0 as f64);
    let mut out = Vec::with_capacity(3);
    for (method, name) in METHODS {
        let levels = match img.gray() {
            Some(_) => None,
            None => img.levels().and_then(|l| {
                let v = l.view(img.width(), img.height())?;
                rfast::Levels::new(v, l.scale).ok()
            }),
        };
        let data = match (img.gray(), levels) {
            (Some(g), _) => fast_band(g, warp, method, r0, &shifted, band)?,
            (None, Some(l)) => fast_band(l, warp, method, r0, &shifted, band)?,
            (None, None) => {
                let grid = rs::warp(img.grid(), band.width, band.height, shifted, method, 0.0);
                grid.data().iter().map(|&v| v as f32).collect()
            }
        };
        out.push(Layer::new(name, band, data, false));
    }
    Ok(out)
}

/// One method's band on the fast path (8-bit bytes or a colour photo's
/// levels): the affine runs for a rotation, the map pixel by pixel for a
/// projective warp.
fn fast_band<S: rfast::Source>(
    src: S,
    warp: &Warp,
    method: Method,
    r0: usize,
    shifted: &dyn Fn(f64, f64) -> (f64, f64),
    band: Region,
) -> Result<Vec<f32>> {
    let mut o = vec![0.0f32; band.width * band.height];
    let size = (band.width, band.height);
    let a = rs::SEED_A;
    match warp.affine {
        Some(m) => {
            // the band's rows: the map's constant part moved down
            let m = [
                [m[0][0], m[0][1], m[0][2] + m[0][1] * r0 as f64],
                [m[1][0], m[1][1], m[1][2] + m[1][1] * r0 as f64],
            ];
            rfast::warp_affine_with(src, &m, shifted, method, a, 0.0, size, &mut o)?
        }
        None => rfast::warp_map(src, shifted, method, a, 0.0, size, &mut o)?,
    }
    Ok(o)
}
