//! Seed 000, Examples 12a/12b and seed 004's cubic convolution: the grey
//! value at a fractional position of a patch by nearest neighbour, bilinear
//! interpolation (the seed's I1, I2 and I) and bicubic interpolation where
//! its 4×4 neighbourhood lies inside the patch; and its practice.

use super::super::drill::{
    drill, mat, or_given, rows_of, tol, BoxDef, Drill, Mistake, Rng, Tolerance,
};
use super::super::fields::{to_rows, Field, Inputs};
use super::super::{Example, Lab};
use crate::error::{Error, Result};
use crate::raster::Grid;
use crate::resample::{self, lerp, Bilinear, SEED_A};
use crate::solution::{
    exact_minus_printed, num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value,
};

/// The largest pixel position accepted for the patch's first pixel.
const MAX_POS: f64 = 1_000_000.0;

pub const EXAMPLE: Example = Example {
    id: "resample",
    title: "Resampling: nearest, bilinear, bicubic",
    source: "Worked examples, Example 12; Lecture 7: Image processing",
    summary: "The grey value at a fractional pixel position: nearest neighbour, bilinear interpolation along the rows then between them, and Lecture 7's cubic convolution.",
    fields,
    solve,
    answer: &["nearest", "bilinear", "bicubic"],
    labels: LABELS,
    lab: Some(Lab::new("resampling", &["window"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// What the result keys mean.
const LABELS: &[(&str, &str, &str)] = &[
    ("nearest_c", "Nearest pixel: column", "px"),
    ("nearest_r", "Nearest pixel: row", "px"),
    ("nearest", "Nearest neighbour value", ""),
    ("i1", "I₁: along the upper row", ""),
    ("i2", "I₂: along the lower row", ""),
    ("bilinear", "Bilinear value I", ""),
    ("bicubic", "Bicubic value (cubic convolution)", ""),
    ("bilinear_rounded", "Bilinear value, whole grey value", ""),
    ("dc", "Column fraction dc", "px"),
    ("dr", "Row fraction dr", "px"),
];

/// Example 12a's patch (seed 000): columns 545…548, rows 817…820.
const EXAMPLE_12A: [[f64; 4]; 4] = [
    [68.0, 64.0, 72.0, 79.0],
    [64.0, 71.0, 78.0, 74.0],
    [61.0, 65.0, 71.0, 78.0],
    [63.0, 56.0, 62.0, 68.0],
];

/// Example 12b's patch (seed 000): columns 523…526, rows 835…838.
const EXAMPLE_12B: [[f64; 4]; 4] = [
    [58.0, 54.0, 66.0, 64.0],
    [54.0, 62.0, 67.0, 59.0],
    [52.0, 57.0, 60.0, 54.0],
    [53.0, 46.0, 52.0, 48.0],
];

fn fields() -> Vec<Field> {
    vec![
        Field::matrix(
            "patch",
            "Patch of grey values",
            &to_rows(&EXAMPLE_12A),
        )
        .help("Rows of grey values. Example 12b: 58 54 66 64; 54 62 67 59; 52 57 60 54; 53 46 52 48 with first pixel (523, 835) and position (523.72, 835.24)."),
        Field::integer("first_c", "Column of the patch's first pixel", 545.0)
            .range(-MAX_POS, MAX_POS)
            .help("Image column of the patch's top-left pixel."),
        Field::integer("first_r", "Row of the patch's first pixel", 817.0)
            .range(-MAX_POS, MAX_POS)
            .help("Image row of the patch's top-left pixel."),
        Field::number("c", "Column c of the position", 547.44)
            .unit("px")
            .range(-2.0 * MAX_POS, 2.0 * MAX_POS)
            .help("Fractional image column; pixel centres are at whole numbers."),
        Field::number("r", "Row r of the position", 817.24)
            .unit("px")
            .range(-2.0 * MAX_POS, 2.0 * MAX_POS)
            .help("Fractional image row; pixel centres are at whole numbers."),
        Field::number("cubic_a", "Cubic convolution parameter a", SEED_A)
            .range(-3.0, 0.0)
            .help("Lecture 7's kernel 1 − 2|x|² + |x|³, 4 − 8|x| + 5|x|² − |x|³ is a = −1; Keys' a = −0.5 reproduces linear ramps exactly."),
    ]
}

/// Why there is no bicubic value at `(c, r)`, and where in the patch (first
/// pixel `first`, last pixel `last`) one would be.
fn no_bicubic_text(at: [f64; 2], first: [f64; 2], last: [f64; 2]) -> String {
    let need = |x: f64| (x.floor() - 1.0, x.floor() + 2.0);
    let ((c0, c1), (r0, r1)) = (need(at[0]), need(at[1]));
    let missing = |lo: f64, hi: f64, from: f64, to: f64, what: &str| -> Option<String> {
        let out: Vec<String> = [lo, lo + 1.0, hi - 1.0, hi]
            .iter()
            .filter(|x| **x < from || **x > to)
            .map(|x| num(*x))
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        (!out.is_empty()).then(|| format!("{what} {}", out.join(" and ")))
    };
    let gaps: Vec<String> = [
        missing(c0, c1, first[0], last[0], "column"),
        missing(r0, r1, first[1], last[1], "row"),
    ]
    .into_iter()
    .flatten()
    .collect();
    let mut text = format!(
        "No bicubic value here: Lecture 7's cubic convolution takes the 16 pixels around the position, columns {} to {} and rows {} to {} for ({}, {}), but the patch covers columns {}–{} and rows {}–{} only ({} missing).",
        num(c0),
        num(c1),
        num(r0),
        num(r1),
        num(at[0]),
        num(at[1]),
        num(first[0]),
        num(last[0]),
        num(first[1]),
        num(last[1]),
        gaps.join(", ")
    );
    // The lecture's case: the position inside the cell between the patch's
    // second and third pixels, so that the 4×4 patch is its neighbourhood.
    if last[0] - first[0] >= 3.0 && last[1] - first[1] >= 3.0 {
        let inside =
            |x: f64, lo: f64, hi: f64| x.floor().clamp(lo + 1.0, hi - 2.0) + (x - x.floor());
        text.push_str(&format!(
            " The lecture's formula Q = [f(1+t) … f(2−t)]·P·[f(1+s) … f(2−s)]ᵀ puts the position between P22, P23, P32 and P33, the middle of a 4×4 patch: with this patch, c = {} and r = {} (the same fractions) give a bicubic value.",
            num(inside(at[0], first[0], last[0])),
            num(inside(at[1], first[1], last[1]))
        ));
    }
    text
}

struct Printed {
    nearest: (f64, f64, f64),
    i1: f64,
    i2: f64,
    bilinear: f64,
    rounded: f64,
}

/// The seed's printed values when the inputs are Example 12a's or 12b's.
fn seed_case(patch: &Grid, fc: f64, fr: f64, c: f64, r: f64) -> Option<(&'static str, Printed)> {
    let is = |m: &[[f64; 4]; 4]| patch.rows() == to_rows(m);
    if is(&EXAMPLE_12A) && (fc, fr, c, r) == (545.0, 817.0, 547.44, 817.24) {
        return Some((
            "12a",
            Printed {
                nearest: (547.0, 817.0, 72.0),
                i1: 75.08,
                i2: 76.24,
                bilinear: 75.35,
                rounded: 75.0,
            },
        ));
    }
    if is(&EXAMPLE_12B) && (fc, fr, c, r) == (523.0, 835.0, 523.72, 835.24) {
        return Some((
            "12b",
            Printed {
                nearest: (524.0, 835.0, 54.0),
                i1: 55.12,
                i2: 59.76,
                bilinear: 56.234,
                rounded: 56.0,
            },
        ));
    }
    None
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let patch = Grid::from_rows("patch", &i.rows("patch")?)?;
    let (fc, fr) = (i.number("first_c")?, i.number("first_r")?);
    let (c, r, a) = (i.number("c")?, i.number("r")?, i.number("cubic_a")?);
    let (w, h) = (patch.width(), patch.height());
    if w < 2 || h < 2 {
        return Err(Error::input(
            "patch",
            format!(
                "is {h}×{w} (rows × columns); bilinear interpolation needs at least 2×2 pixels"
            ),
        ));
    }
    let (last_c, last_r) = (fc + w as f64 - 1.0, fr + h as f64 - 1.0);
    if !(fc..=last_c).contains(&c) {
        return Err(Error::input(
            "c",
            format!(
                "{} is outside the patch: its pixel centres run from column {} to {}",
                num(c),
                num(fc),
                num(last_c)
            ),
        ));
    }
    if !(fr..=last_r).contains(&r) {
        return Err(Error::input(
            "r",
            format!(
                "{} is outside the patch: its pixel centres run from row {} to {}",
                num(r),
                num(fr),
                num(last_r)
            ),
        ));
    }
    let (x, y) = (c - fc, r - fr);
    let near = resample::nearest(&patch, x, y)
        .ok_or_else(|| Error::Internal("nearest pixel outside a checked patch".into()))?;
    let bl = resample::bilinear(&patch, x, y)
        .ok_or_else(|| Error::Internal("bilinear neighbourhood outside a checked patch".into()))?;
    let bc = resample::bicubic(&patch, x, y, a);

    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(
        Step::new(
            "Position in the patch",
            "Pixel centres sit at whole column and row numbers; the patch starts at its first pixel.",
        )
        .relation(
            Relation::new("x")
                .key("x")
                .sym(r"c - c_{\text{first}}")
                .subst(format!("{} - {}", num(c), num(fc)))
                .value(x, ""),
        )
        .relation(
            Relation::new("y")
                .key("y")
                .sym(r"r - r_{\text{first}}")
                .subst(format!("{} - {}", num(r), num(fr)))
                .value(y, ""),
        )
        .value("patch", Value::matrix(&patch.rows()))
        .value("first_c", fc)
        .value("first_r", fr)
        .value("x", x)
        .value("y", y),
    );
    let (nc, nr) = (fc + near.c as f64, fr + near.r as f64);
    s.step(
        Step::new(
            "Nearest neighbour",
            "Round the column and the row to the nearest whole numbers and take that pixel's grey value.",
        )
        .relation(
            Relation::new(r"I_{\text{NN}}")
                .key("nearest")
                .sym(r"DN_{[c + 0.5],\,[r + 0.5]}")
                .subst(format!(r"DN_{{{},\,{}}}", num(nc), num(nr)))
                .value(near.value, ""),
        )
        .value("nearest_c", nc)
        .value("nearest_r", nr)
        .value("nearest", near.value),
    );
    let (c0, r0) = (fc + bl.c as f64, fr + bl.r as f64);
    let [p00, p10, p01, p11] = bl.p;
    s.step(
        Step::new(
            "Bilinear: the four surrounding pixels",
            &format!(
                "The pixels of columns {} and {} in rows {} and {}; the position lies dc = {} of a pixel to the right of the left ones and dr = {} below the upper ones.",
                num(c0),
                num(c0 + 1.0),
                num(r0),
                num(r0 + 1.0),
                num(bl.dc),
                num(bl.dr)
            ),
        )
        .relation(
            Relation::new(Form::grid_tex(
                "bmatrix",
                vec![
                    vec![r"DN_{c_1,r_1}".into(), r"DN_{c_2,r_1}".into()],
                    vec![r"DN_{c_1,r_2}".into(), r"DN_{c_2,r_2}".into()],
                ],
                "",
            ))
            .key("corners")
            .result(Form::grid("bmatrix", &[vec![p00, p10], vec![p01, p11]], "")),
        )
        .relation(
            Relation::new("dc")
                .key("dc")
                .sym("c - c_1")
                .subst(format!("{} - {}", num(c), num(c0)))
                .value(bl.dc, ""),
        )
        .relation(
            Relation::new("dr")
                .key("dr")
                .sym("r - r_1")
                .subst(format!("{} - {}", num(r), num(r0)))
                .value(bl.dr, ""),
        )
        .value("bilinear_c", c0)
        .value("bilinear_r", r0)
        .value("dc", bl.dc)
        .value("dr", bl.dr)
        .value("corners", Value::numbers(&bl.p))
        .value("weights", Value::numbers(&bl.weights())),
    );
    s.step(
        Step::new(
            "Bilinear: along the upper row",
            &format!("Interpolate between the two pixels of row {}.", num(r0)),
        )
        .relation(
            Relation::new("I_1")
                .key("i1")
                .sym(r"DN_{c,r} + dc\,(DN_{c+1,r} - DN_{c,r})")
                .subst(lerp_tex(p00, bl.dc, p10))
                .value(bl.i1, ""),
        )
        .value("i1", bl.i1),
    );
    s.step(
        Step::new(
            "Bilinear: along the lower row",
            &format!("The same between the two pixels of row {}.", num(r0 + 1.0)),
        )
        .relation(
            Relation::new("I_2")
                .key("i2")
                .sym(r"DN_{c,r+1} + dc\,(DN_{c+1,r+1} - DN_{c,r+1})")
                .subst(lerp_tex(p01, bl.dc, p11))
                .value(bl.i2, ""),
        )
        .value("i2", bl.i2),
    );
    s.step(
        Step::new(
            "Bilinear: between the rows",
            "Interpolate between I1 and I2 along the column; a grey value is then rounded to a whole number.",
        )
        .relation(
            Relation::new("I")
                .key("bilinear")
                .sym(r"I_1 + dr\,(I_2 - I_1)")
                .subst(lerp_tex(bl.i1, bl.dr, bl.i2))
                .value(bl.value, ""),
        )
        .relation(
            Relation::new("I")
                .key("bilinear_rounded")
                .op(r"\approx")
                .value(bl.value.round(), ""),
        )
        .value("bilinear", bl.value)
        .value("weights", Value::numbers(&bl.weights())),
    );
    match &bc {
        Some(b) => {
            let (bc0, br0) = (fc + b.c as f64, fr + b.r as f64);
            let p = to_rows(&b.p);
            let w = |v: &[f64; 4]| Value::numbers(v);
            s.step(
                Step::new(
                    "Bicubic: weights",
                    &format!(
                        "Lecture 7's cubic convolution uses the 4×4 pixels from column {} and row {}. With s = c − [c] and t = r − [r] the kernel gives four weights per direction (they sum to 1).",
                        num(bc0),
                        num(br0)
                    ),
                )
                .relation(
                    Relation::new("f(x)").sym(
                        r"\begin{cases} (a+2)|x|^3 - (a+3)|x|^2 + 1 & |x| < 1 \\ a|x|^3 - 5a|x|^2 + 8a|x| - 4a & 1 \le |x| < 2 \\ 0 & 2 \le |x| \end{cases}",
                    ),
                )
                .relation(Relation::new("a").key("cubic_a").value(b.a, ""))
                .relation(
                    Relation::new("s")
                        .key("s")
                        .subst(format!("{} - {}", num(c), num(c.floor())))
                        .value(b.s, ""),
                )
                .relation(
                    Relation::new(r"[f(1+s),\,f(s),\,f(1-s),\,f(2-s)]")
                        .key("weights_c")
                        .result(vector_tex(&b.wc)),
                )
                .relation(
                    Relation::new("t")
                        .key("t")
                        .subst(format!("{} - {}", num(r), num(r.floor())))
                        .value(b.t, ""),
                )
                .relation(
                    Relation::new(r"[f(1+t),\,f(t),\,f(1-t),\,f(2-t)]")
                        .key("weights_r")
                        .result(vector_tex(&b.wr)),
                )
                .value("bicubic_c", bc0)
                .value("bicubic_r", br0)
                .value("s", b.s)
                .value("t", b.t)
                .value("weights_c", w(&b.wc))
                .value("weights_r", w(&b.wr)),
            );
            s.step(
                Step::new(
                    "Bicubic: the 4×4 product",
                    "Each row of P weighted along the columns, then the four row values weighted along the rows.",
                )
                .relation(
                    Relation::new("P")
                        .key("neighbourhood")
                        .result(Form::grid("bmatrix", &p, "P")),
                )
                .relation(
                    Relation::new(r"P\,w_c")
                        .key("row_values")
                        .result(format!("{}^T", vector_tex(&b.rows))),
                )
                .relation(
                    Relation::new("Q")
                        .key("bicubic")
                        .sym(r"[f(1+t)\ f(t)\ f(1-t)\ f(2-t)]\; P \;[f(1+s)\ f(s)\ f(1-s)\ f(2-s)]^T")
                        .subst(format!(
                            r"{}\;{}^T",
                            vector_tex(&b.wr),
                            vector_tex(&b.rows)
                        ))
                        .value(b.value, ""),
                )
                .value("neighbourhood", Value::matrix(&p))
                .value("row_values", w(&b.rows))
                .value("bicubic", b.value),
            );
        }
        None => {
            s.note(
                NoteKind::Warning,
                no_bicubic_text([c, r], [fc, fr], [last_c, last_r]),
            )
            .about(&["bicubic"]);
        }
    }
    s.result = Record::new()
        .with("nearest_c", nc)
        .with("nearest_r", nr)
        .with("nearest", near.value)
        .with("i1", bl.i1)
        .with("i2", bl.i2)
        .with("bilinear", bl.value)
        .with("bicubic", bc.as_ref().map(|b| b.value))
        .with("bilinear_rounded", bl.value.round())
        .with("dc", bl.dc)
        .with("dr", bl.dr);
    s.note(
        NoteKind::Convention,
        "Pixel centres are at whole column and row numbers, so column 547.44 lies 0.44 of a pixel right of pixel 547's centre. Nearest neighbour rounds halves up (547.5 → 548).",
    ).about(&["nearest_c", "nearest_r", "nearest"]);
    if a != SEED_A {
        s.note(
            NoteKind::Convention,
            format!(
                "The cubic kernel uses a = {} instead of Lecture 7's a = −1.",
                num(a)
            ),
        )
        .about(&["bicubic"]);
    } else {
        s.note(
            NoteKind::Convention,
            "Lecture 7's cubic kernel (a = −1) passes through the samples, but it does not reproduce a linear ramp between them: on grey values rising by g per pixel it is off by s(1 − s)(1 − 2s)·g at the fraction s, up to 0.096·g. Keys' a = −0.5 (choose it above) reproduces ramps exactly.",
        ).about(&["bicubic"]);
    }
    if let Some((which, p)) = seed_case(&patch, fc, fr, c, r) {
        s.textbook = Some(
            Record::new()
                .with("nearest_c", p.nearest.0)
                .with("nearest_r", p.nearest.1)
                .with("nearest", p.nearest.2)
                .with("i1", p.i1)
                .with("i2", p.i2)
                .with("bilinear", p.bilinear)
                .with("bilinear_rounded", p.rounded),
        );
        if which == "12a" {
            s.note(
                NoteKind::Convention,
                format!(
                    "For the lower row the course notes interpolate from the right pixel: I2 = 74 + 0.56·(78 − 74) = 76.24, with 1 − dc = 0.56. That is the same as 78 + 0.44·(74 − 78) = {} from the left, as I1 is done.",
                    num(bl.i2)
                ),
            ).about(&["i2"]);
            s.note(
                NoteKind::Rounding,
                format!(
                    "The course notes' I = 75.08 + 0.2784 = {} is printed 75.35: cut off, not rounded (75.36; {}). The whole grey value 75 is right.",
                    num(bl.value),
                    exact_minus_printed(bl.value, 75.35, "")
                ),
            ).about(&["bilinear"]);
        } else {
            s.note(
                NoteKind::Erratum,
                "Harmless: the course notes write the position as c = 523.72m, with a stray unit m (metres); it is a pixel column.",
            );
            s.note(
                NoteKind::Rounding,
                format!(
                    "The course notes print I = 55.12 + 0.24·(59.76 − 55.12) = {} as 56.234, rounded to three decimals; every value of Example 12b is right.",
                    num(bl.value)
                ),
            ).about(&["bilinear"]);
        }
    }
    Ok(s)
}

/// `a + t\,(b - a)`: one linear interpolation written out.
fn lerp_tex(a: f64, t: f64, b: f64) -> String {
    format!(r"{} + {}\,({} - {})", num(a), num(t), num(b), tex(a))
}

/// A short row of numbers: `[0.1,\,0.2,\,0.7]`.
fn vector_tex(xs: &[f64]) -> String {
    let cells: Vec<String> = xs.iter().map(|x| num(*x)).collect();
    format!("[{}]", cells.join(r",\,"))
}

// ---------------------------------------------------------------------------
// Practice

/// A fraction in 0.05–0.95 with two decimals, never one half (so the
/// nearest pixel is never a tie).
fn fraction(rng: &mut Rng) -> f64 {
    let k = rng.int(5, 94);
    let k = if k == 50 { 51 } else { k };
    k as f64 / 100.0
}

fn generate(rng: &mut Rng) -> Record {
    let patch: Vec<Vec<f64>> = (0..4)
        .map(|_| (0..4).map(|_| rng.num(40, 90)).collect())
        .collect();
    let (first_c, first_r) = (rng.num(100, 900), rng.num(100, 900));
    // Inside the central cell so that bicubic has its 4×4 neighbourhood.
    let c = first_c + 1.0 + fraction(rng);
    let r = first_r + 1.0 + fraction(rng);
    Record::new()
        .with("patch", mat(&patch))
        .with("first_c", first_c)
        .with("first_r", first_r)
        .with("c", (c * 100.0).round() / 100.0)
        .with("r", (r * 100.0).round() / 100.0)
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("nearest", "Nearest neighbour", None, tol::WHOLE)
            .nudge("Round c and r to the nearest whole pixel and read its grey value."),
        BoxDef::new("i1", "Upper row interpolated I₁", None, tol::GREY)
            .nudge("Along the upper row of the 2×2 neighbourhood: move the fraction Δc from the left pixel to the right one."),
        BoxDef::new("i2", "Lower row interpolated I₂", None, tol::GREY)
            .nudge("The same along the lower row."),
        BoxDef::new("bilinear", "Bilinear value", None, tol::GREY)
            .nudge("Now between I₁ and I₂ by the fraction Δr."),
        BoxDef::new("bicubic", "Bicubic value", None, Tolerance::abs(0.05))
            .nudge("Cubic-convolution weights for the four columns and four rows of the 4×4 patch."),
    ]
}

/// The core's bilinear interpolation of a drawn variant, with its 2×2
/// neighbourhood and fractions.
fn bilinear_of(i: &Record) -> Result<Bilinear> {
    let patch = Grid::from_rows("patch", &rows_of(i, "patch"))?;
    let n = |k: &str| i.number(k).unwrap_or(f64::NAN);
    resample::bilinear(&patch, n("c") - n("first_c"), n("r") - n("first_r"))
        .ok_or_else(|| Error::Internal("a drawn position outside its patch".into()))
}

/// The bilinear boxes from the student's I₁ and I₂: the core's stages.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let b = bilinear_of(i)?;
    let i1 = or_given(g, "i1", b.i1);
    let i2 = or_given(g, "i2", b.i2);
    Ok(Record::new()
        .with("nearest", s.result.number("nearest").unwrap_or(f64::NAN))
        .with("i1", i1)
        .with("i2", i2)
        .with("bilinear", or_given(g, "bilinear", lerp(i1, i2, b.dr)))
        .with("bicubic", s.result.number("bicubic").unwrap_or(f64::NAN)))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let b = bilinear_of(i)?;
    let [p00, p10, p01, p11] = b.p;
    const SWAP: &str = "The pixel the position is nearer to gets the larger weight: the left pixel's weight is 1 − Δc, the right one's Δc.";
    let i1 = lerp(p00, p10, 1.0 - b.dc);
    let i2 = lerp(p01, p11, 1.0 - b.dc);
    let keys = EXAMPLE.run(&i.clone().with("cubic_a", -0.5))?;
    Ok(vec![
        Mistake::new(
            "nearest",
            "rounded down",
            "Nearest means rounding to the nearest pixel, not cutting the fraction off.",
            p00,
        ),
        Mistake::new("i1", "bilinear weights swapped", SWAP, i1),
        Mistake::new("i2", "bilinear weights swapped", SWAP, i2),
        Mistake::new(
            "bilinear",
            "bilinear weights swapped",
            SWAP,
            lerp(i1, i2, 1.0 - b.dr),
        ),
        Mistake::new(
            "bilinear",
            "rows and columns swapped",
            "Δc moves along a row (between columns), Δr down a column.",
            lerp(lerp(p00, p10, b.dr), lerp(p01, p11, b.dr), b.dc),
        ),
        Mistake::new(
            "bicubic",
            "Keys' a = −0.5 instead of the seed's kernel",
            "Seed 004's kernel 1 − 2|x|² + |x|³ is cubic convolution with a = −1.",
            keys.result.number("bicubic").unwrap_or(f64::NAN),
        ),
    ])
}
