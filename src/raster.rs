//! The grid of numbers every image operator works on: row-major, `width`
//! columns (`c`, to the right) by `height` rows (`r`, downward), zero-based
//! in the core (the worked examples show positions from 1, as the seeds do).
//! Access is checked; what happens outside the grid is a [`Border`] policy.

use crate::error::{Error, Result};

/// What a read outside the grid returns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Border {
    /// The nearest edge pixel (`aaa|abc|ccc`).
    Replicate,
    /// Mirrored about the edge pixel (`cb|abc|ba`).
    Reflect,
    /// Zero outside.
    Zero,
    /// No value outside: operators keep only the interior where they fit.
    Crop,
}

/// The index inside `0..n` that position `x` reads under `border`:
/// the nearest edge (`Replicate`), mirrored about the edge pixel
/// (`Reflect`), `None` outside for `Zero` and `Crop` (and for `n = 0`).
/// The one place the border rule is written; [`Grid::at`] and the fast
/// image paths both use it.
pub fn fold(x: isize, n: usize, border: Border) -> Option<usize> {
    let n = n as isize;
    if n == 0 {
        return None;
    }
    if (0..n).contains(&x) {
        return Some(x as usize);
    }
    match border {
        Border::Replicate => Some(x.clamp(0, n - 1) as usize),
        Border::Zero | Border::Crop => None,
        Border::Reflect if n == 1 => Some(0),
        Border::Reflect => {
            let period = 2 * (n - 1);
            let m = x.rem_euclid(period);
            Some((if m < n { m } else { period - m }) as usize)
        }
    }
}

/// A rectangular grid of finite numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    width: usize,
    height: usize,
    data: Vec<f64>,
}

impl Grid {
    /// A grid from row-major `data`; `field` names the input in errors.
    pub fn new(field: &str, width: usize, height: usize, data: Vec<f64>) -> Result<Self> {
        if width == 0 || height == 0 {
            return Err(Error::input(field, "is empty"));
        }
        if data.len() != width * height {
            return Err(Error::input(
                field,
                format!("has {} values for {width}×{height}", data.len()),
            ));
        }
        if let Some(i) = data.iter().position(|x| !x.is_finite()) {
            return Err(Error::input(
                field,
                format!(
                    "value at row {}, column {} is not a finite number",
                    i / width + 1,
                    i % width + 1
                ),
            ));
        }
        Ok(Grid {
            width,
            height,
            data,
        })
    }

    /// A grid from a list of rows (all the same length).
    pub fn from_rows(field: &str, rows: &[Vec<f64>]) -> Result<Self> {
        let width = rows.first().map_or(0, Vec::len);
        if let Some((i, row)) = rows.iter().enumerate().find(|(_, r)| r.len() != width) {
            return Err(Error::input(
                field,
                format!(
                    "rows must all have the same length: row 1 has {width}, row {} has {}",
                    i + 1,
                    row.len()
                ),
            ));
        }
        Grid::new(field, width, rows.len(), rows.concat())
    }

    /// A grid of `width × height` filled with `value`.
    pub fn filled(width: usize, height: usize, value: f64) -> Self {
        Grid {
            width,
            height,
            data: vec![value; width * height],
        }
    }

    /// A grid whose value at `(c, r)` is `f(c, r)`.
    pub fn from_fn(width: usize, height: usize, f: impl Fn(usize, usize) -> f64) -> Self {
        let mut data = Vec::with_capacity(width * height);
        for r in 0..height {
            for c in 0..width {
                data.push(f(c, r));
            }
        }
        Grid {
            width,
            height,
            data,
        }
    }

    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }
    /// The values, row-major.
    pub fn data(&self) -> &[f64] {
        &self.data
    }

    /// The value at column `c`, row `r`, or `None` outside.
    pub fn get(&self, c: usize, r: usize) -> Option<f64> {
        (c < self.width && r < self.height).then(|| self.data[r * self.width + c])
    }

    /// Sets the value at `(c, r)`; returns false (and changes nothing) outside.
    pub fn set(&mut self, c: usize, r: usize, value: f64) -> bool {
        if c < self.width && r < self.height {
            self.data[r * self.width + c] = value;
            true
        } else {
            false
        }
    }

    /// The value at a possibly outside position under a border policy
    /// (`None` only with [`Border::Crop`] outside).
    pub fn at(&self, c: isize, r: isize, border: Border) -> Option<f64> {
        let inside = |x: isize, n: usize| (0..n as isize).contains(&x);
        if inside(c, self.width) && inside(r, self.height) {
            return self.get(c as usize, r as usize);
        }
        match border {
            Border::Crop => None,
            Border::Zero => Some(0.0),
            Border::Replicate | Border::Reflect => {
                self.get(fold(c, self.width, border)?, fold(r, self.height, border)?)
            }
        }
    }

    /// The `w × h` sub-grid whose top-left is `(c, r)`, if it fits.
    pub fn window(&self, c: usize, r: usize, w: usize, h: usize) -> Option<Grid> {
        if w == 0 || h == 0 || c + w > self.width || r + h > self.height {
            return None;
        }
        Some(Grid::from_fn(w, h, |i, j| {
            self.data[(r + j) * self.width + c + i]
        }))
    }

    /// The rows as vectors (for results and steps).
    pub fn rows(&self) -> Vec<Vec<f64>> {
        self.data.chunks(self.width).map(<[f64]>::to_vec).collect()
    }
}

/// A grey image borrowed from a buffer of `T` (row-major, no padding):
/// [`Gray`] (bytes) and [`GrayF32`] (`f32` values) are its two kinds.
#[derive(Debug, Clone, Copy)]
pub struct Plane<'a, T> {
    data: &'a [T],
    width: usize,
    height: usize,
}

/// What a [`Plane`] may hold: the word its errors count the buffer in, and
/// whether a value is one (an `f32` must be finite).
pub trait PlaneValue: Copy {
    /// "bytes", "values".
    const UNIT: &'static str;
    fn valid(self) -> bool;
}

impl PlaneValue for u8 {
    const UNIT: &'static str = "bytes";
    fn valid(self) -> bool {
        true
    }
}

impl PlaneValue for f32 {
    const UNIT: &'static str = "values";
    fn valid(self) -> bool {
        self.is_finite()
    }
}

/// An 8-bit grey image borrowed from a byte buffer: the input of the fast
/// whole-image paths (`filter::fast`, `interest::fast`, `correlation::fast`,
/// `resample::fast`, `chain::fast`).
pub type Gray<'a> = Plane<'a, u8>;

/// A grey image of `f32` values borrowed from a buffer: the input of the
/// fast filter passes when the grey values are not bytes
/// (`filter::fast::{separable, correlate, sobel, median3_f32}` read it as
/// they read a [`Gray`]'s converted rows). The image lab gives a colour
/// photo's greys as the whole numbers `n = s · grey` (its BT.601 sums),
/// exact in `f32`, so that the passes' sums are exact integers.
pub type GrayF32<'a> = Plane<'a, f32>;

impl<'a, T: PlaneValue> Plane<'a, T> {
    /// A view of `data` as `width × height`; `field` names it in errors
    /// (an `f32` value must be finite).
    pub fn new(field: &str, data: &'a [T], width: usize, height: usize) -> Result<Self> {
        if width == 0 || height == 0 {
            return Err(Error::input(field, "is empty"));
        }
        if width.checked_mul(height) != Some(data.len()) {
            return Err(Error::input(
                field,
                format!("has {} {} for {width}×{height}", data.len(), T::UNIT),
            ));
        }
        if !data.iter().all(|v| v.valid()) {
            return Err(Error::input(field, "must hold finite numbers"));
        }
        Ok(Plane {
            data,
            width,
            height,
        })
    }
    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }
    pub fn data(&self) -> &'a [T] {
        self.data
    }
    /// Row `r` (`None` past the last row).
    pub fn row(&self, r: usize) -> Option<&'a [T]> {
        self.data.get(r * self.width..(r + 1) * self.width)
    }
}

impl Gray<'_> {
    /// The same values as a [`Grid`] (what the reference functions take).
    pub fn to_grid(&self) -> Grid {
        Grid {
            width: self.width,
            height: self.height,
            data: self.data.iter().map(|&v| f64::from(v)).collect(),
        }
    }
}

impl Grid {
    /// The values as bytes when every one is a whole number in 0 … 255
    /// (an 8-bit image), so that a fast 8-bit path gives the same result.
    pub fn to_u8(&self) -> Option<Vec<u8>> {
        self.data
            .iter()
            .map(|&v| (v.fract() == 0.0 && (0.0..=255.0).contains(&v)).then_some(v as u8))
            .collect()
    }
}

/// Checks that an output buffer holds `n` values; `field` names it.
pub fn check_len<T>(field: &str, out: &[T], n: usize) -> Result<()> {
    if out.len() != n {
        return Err(Error::input(
            field,
            format!("has room for {} values, the image has {n}", out.len()),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checked_access_and_windows() {
        let g = Grid::from_rows("g", &[vec![1.0, 2.0, 3.0], vec![4.0, 5.0, 6.0]]).unwrap();
        assert_eq!((g.width(), g.height()), (3, 2));
        assert_eq!(g.get(2, 1), Some(6.0));
        assert_eq!(g.get(3, 0), None);
        assert_eq!(
            g.window(1, 0, 2, 2).unwrap().rows(),
            vec![vec![2.0, 3.0], vec![5.0, 6.0]]
        );
        assert!(g.window(2, 0, 2, 1).is_none());
    }

    #[test]
    fn border_policies() {
        let g = Grid::from_rows("g", &[vec![1.0, 2.0, 3.0]]).unwrap();
        assert_eq!(g.at(-1, 0, Border::Replicate), Some(1.0));
        assert_eq!(g.at(-1, 0, Border::Reflect), Some(2.0));
        assert_eq!(g.at(4, 0, Border::Reflect), Some(1.0));
        assert_eq!(g.at(3, 0, Border::Zero), Some(0.0));
        assert_eq!(g.at(3, 0, Border::Crop), None);
        assert_eq!(g.at(0, -2, Border::Reflect), Some(1.0));
    }

    #[test]
    fn bad_grids_name_the_field() {
        let e = Grid::from_rows("window", &[vec![1.0, 2.0], vec![3.0]]).unwrap_err();
        assert_eq!(e.field(), Some("window"));
        assert!(Grid::from_rows("window", &[]).is_err());
        let e = Grid::new("w", 1, 1, vec![f64::NAN]).unwrap_err();
        assert!(e.to_string().contains("row 1, column 1"), "{e}");
    }
}
