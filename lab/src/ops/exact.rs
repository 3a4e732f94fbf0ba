//! The operators of the menu with their parameters ([`Op`]): how many rows
//! of real neighbours a band needs ([`halo`]), and the exact number of one
//! pixel of a layer ([`exact_at`]): the reference function on that pixel's
//! window — the number the worked example computes, where the layer holds
//! its `f32` rounding (or the fast path's value within the stated
//! tolerance).

use super::*;
use photogrammetry_playground::interest::{self, fast::stream};
use photogrammetry_playground::resample::{self as rs};

/// An operator of the lab's menu and its parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// `kernel` by name (`custom`: with its rows and divisor), or `median`.
    Filter {
        kernel: String,
        border: Border,
        custom: Option<(Vec<Vec<f64>>, f64)>,
    },
    /// `prewitt` or `sobel`.
    Edges {
        operator: String,
        border: Border,
    },
    Forstner {
        size: usize,
    },
    Moravec {
        size: usize,
    },
    /// [`Warp::new`]'s parameters.
    Resample {
        kind: String,
        params: Vec<f64>,
        width: usize,
        height: usize,
    },
    /// The template box of the first image over the search box of the
    /// second.
    Correlation {
        template: Rect,
        search: Rect,
    },
}

/// Rows of real neighbours a band of rows needs above and below so that
/// its own rows of every layer (and, for the interest operators, its
/// points) equal the whole image's at every pixel; `None` for operators
/// that do not run by bands of input rows (resampling runs by bands of
/// output rows over the whole input: [`resample`]'s `rows`; correlation and
/// boundaries are one search box and one region).
///
/// Filters and edges: half the kernel's height (the border policy then
/// acts only at the image's own edges). Förstner and Moravec: the window's
/// reach below its reference pixel (`size − 1 − anchor`; the anchor above
/// is never more) for the maps, plus the suppression radius `size / 2` so
/// that the scores a kept point is compared with are the whole image's.
pub fn halo(op: &Op) -> Result<Option<usize>> {
    Ok(match op {
        Op::Filter {
            kernel: name,
            custom,
            ..
        } => Some(
            match kernel(name, custom.as_ref().map(|(r, d)| (r.as_slice(), *d)))? {
                Some(k) => k.half_height(),
                None => 1,
            },
        ),
        Op::Edges { operator, .. } => {
            edge_kernels(operator)?;
            Some(1)
        }
        Op::Forstner { size } | Op::Moravec { size } => {
            stream::fit(*size, *size, *size)?;
            Some(stream::reach(*size) + size / 2)
        }
        Op::Resample { .. } | Op::Correlation { .. } => None,
    })
}

/// The exact value (the reference function on the pixel's window: the
/// worked example's number) of layer `layer` of `op` at pixel `(c, r)` —
/// input pixel for filters, edges and the interest maps, output pixel for
/// resampling, template centre for the correlation surface (`second`: the
/// search image). `None` where the layer has no value there.
pub fn exact_at(
    img: &Grid,
    second: &Grid,
    op: &Op,
    layer: &str,
    c: usize,
    r: usize,
) -> Result<Option<f64>> {
    Ok(match op {
        Op::Filter {
            kernel: name,
            border,
            custom,
        } => match kernel(name, custom.as_ref().map(|(r, d)| (r.as_slice(), *d)))? {
            Some(k) => filter::pixel_sum(img, &k, c, r, *border).map(|p| p.value),
            None => {
                filter::neighbourhood(img, c, r, 3, 3, *border).and_then(|v| filter::median_of(&v))
            }
        },
        Op::Edges { operator, border } => {
            let (kx, ky) = edge_kernels(operator)?;
            let gx = filter::pixel_sum(img, &kx, c, r, *border).map(|p| p.value);
            let gy = filter::pixel_sum(img, &ky, c, r, *border).map(|p| p.value);
            let both = gx.zip(gy);
            match layer {
                "gx" => gx,
                "gy" => gy,
                "magnitude" => both.map(|(x, y)| x.hypot(y)),
                "direction" => both.map(|(x, y)| y.atan2(x).to_degrees()),
                _ => return Err(unknown_layer(layer, "gx, gy, magnitude or direction")),
            }
        }
        Op::Forstner { size } => {
            stream::fit(img.width(), img.height(), *size)?;
            let m = interest::window_at(img, c, r, *size)
                .map(|w| interest::forstner(&w))
                .transpose()?
                .map(|f| f.measures);
            match layer {
                "w" => m.map(|m| m.w),
                "q" => m.and_then(|m| m.q),
                _ => return Err(unknown_layer(layer, "w or q")),
            }
        }
        Op::Moravec { size } => {
            stream::fit(img.width(), img.height(), *size)?;
            interest::window_at(img, c, r, *size)
                .map(|w| interest::moravec(&w))
                .transpose()?
                .map(|m| m.mean)
        }
        Op::Resample {
            kind,
            params,
            width,
            height,
        } => {
            let warp = Warp::new((img.width(), img.height()), kind, params, *width, *height)?;
            let method = METHODS
                .iter()
                .find(|(_, n)| *n == layer)
                .map(|(m, _)| *m)
                .ok_or_else(|| unknown_layer(layer, "nearest, bilinear or bicubic"))?;
            (c < *width && r < *height).then(|| {
                let (x, y) = warp.position(c as f64, r as f64);
                rs::value_at(img, x, y, method).unwrap_or(0.0)
            })
        }
        Op::Correlation { template, search } => {
            let t = cut(img, "template", *template)?;
            let s = cut(second, "search", *search)?;
            let (hw, hh) = (template.width / 2, template.height / 2);
            let (i, j) = (c.checked_sub(search.c0 + hw), r.checked_sub(search.r0 + hh));
            match i.zip(j) {
                Some((i, j)) => s
                    .window(i, j, t.width(), t.height())
                    .and_then(|win| correlation_rho(&t, &win)),
                None => None,
            }
        }
    })
}

fn correlation_rho(t: &Grid, win: &Grid) -> Option<f64> {
    photogrammetry_playground::correlation::ncc(t.data(), win.data())
        .ok()?
        .rho
}

fn unknown_layer(layer: &str, known: &str) -> Error {
    Error::input(
        "layer",
        format!("must be {known} (got \"{}\")", short(layer)),
    )
}
