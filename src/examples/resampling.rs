//! Seed 000, Examples 12a/12b and seed 004's cubic convolution: the grey
//! value at a fractional position of a patch by nearest neighbour, bilinear
//! interpolation (the seed's I1, I2 and I) and bicubic interpolation where
//! its 4×4 neighbourhood lies inside the patch.

use super::fields::{Field, Inputs};
use super::filters::{bmatrix, matrix_field, rows};
use super::{Example, Lab, Topic};
use crate::error::{Error, Result};
use crate::raster::Grid;
use crate::resample::{self, SEED_A};
use crate::solution::{exact_minus_printed, num, tex, NoteKind, Record, Solution, Step, Value};

const TITLE: &str = "Resampling";
/// The largest pixel position accepted for the patch's first pixel.
const MAX_POS: f64 = 1_000_000.0;

/// Example 12a's patch (seed 000): columns 545…548, rows 817…820.
pub const EXAMPLE_12A: [[f64; 4]; 4] = [
    [68.0, 64.0, 72.0, 79.0],
    [64.0, 71.0, 78.0, 74.0],
    [61.0, 65.0, 71.0, 78.0],
    [63.0, 56.0, 62.0, 68.0],
];

/// Example 12b's patch (seed 000): columns 523…526, rows 835…838.
pub const EXAMPLE_12B: [[f64; 4]; 4] = [
    [58.0, 54.0, 66.0, 64.0],
    [54.0, 62.0, 67.0, 59.0],
    [52.0, 57.0, 60.0, 54.0],
    [53.0, 46.0, 52.0, 48.0],
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[Example {
        id: "resample",
        title: "Resampling: nearest, bilinear, bicubic",
        source: "Worked examples, Example 12; Lecture 7: Image processing",
        summary: "The grey value at a fractional pixel position: nearest neighbour, bilinear interpolation along the rows then between them, and Lecture 7's cubic convolution.",
        fields,
        solve,
        answer: &["nearest", "bilinear", "bicubic"],
        labels: &[],
        lab: Some(Lab { family: "resampling", explains: &[] }),
        practice: None,
    }];

/// The topic: its module (`web/resampling/`) and title.
pub const TOPIC: Topic = Topic {
    module: "resampling",
    title: TITLE,
    examples: EXAMPLES,
};

fn fields() -> Vec<Field> {
    vec![
        matrix_field(
            "patch",
            "Patch of grey values",
            &EXAMPLE_12A.iter().map(|r| r.to_vec()).collect::<Vec<_>>(),
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
    let is = |m: &[[f64; 4]; 4]| patch.rows() == m.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
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
    let patch = Grid::from_rows("patch", &rows(inputs, "patch")?)?;
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

    let mut s = Solution::new(
        "resample",
        "Resampling: nearest, bilinear, bicubic",
        inputs.clone(),
    );
    s.step(
        Step::new(
            "Position in the patch",
            "Pixel centres sit at whole column and row numbers; the patch starts at its first pixel.",
        )
        .formula(
            r"x = c - c_{\text{first}},\quad y = r - r_{\text{first}}",
            format!(
                r"x = {} - {} = {},\quad y = {} - {} = {}",
                num(c),
                num(fc),
                num(x),
                num(r),
                num(fr),
                num(y)
            ),
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
        .formula(
            r"I_{\text{NN}} = DN_{[c + 0.5],\,[r + 0.5]}",
            format!(r"I_{{\text{{NN}}}} = DN_{{{},\,{}}} = {}", num(nc), num(nr), num(near.value)),
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
        .formula(
            r"dc = c - c_1,\quad dr = r - r_1",
            format!(
                r"\begin{{bmatrix}} DN_{{c_1,r_1}} & DN_{{c_2,r_1}} \\ DN_{{c_1,r_2}} & DN_{{c_2,r_2}} \end{{bmatrix}} = {},\quad dc = {},\quad dr = {}",
                bmatrix(&[vec![p00, p10], vec![p01, p11]]),
                num(bl.dc),
                num(bl.dr)
            ),
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
        .formula(
            r"I_1 = DN_{c,r} + dc\,(DN_{c+1,r} - DN_{c,r})",
            format!(
                r"I_1 = {} + {}\,({} - {}) = {}",
                num(p00),
                num(bl.dc),
                num(p10),
                tex(p00),
                num(bl.i1)
            ),
        )
        .value("i1", bl.i1),
    );
    s.step(
        Step::new(
            "Bilinear: along the lower row",
            &format!("The same between the two pixels of row {}.", num(r0 + 1.0)),
        )
        .formula(
            r"I_2 = DN_{c,r+1} + dc\,(DN_{c+1,r+1} - DN_{c,r+1})",
            format!(
                r"I_2 = {} + {}\,({} - {}) = {}",
                num(p01),
                num(bl.dc),
                num(p11),
                tex(p01),
                num(bl.i2)
            ),
        )
        .value("i2", bl.i2),
    );
    s.step(
        Step::new(
            "Bilinear: between the rows",
            "Interpolate between I1 and I2 along the column; a grey value is then rounded to a whole number.",
        )
        .formula(
            r"I = I_1 + dr\,(I_2 - I_1)",
            format!(
                r"I = {} + {}\,({} - {}) = {} \approx {}",
                num(bl.i1),
                num(bl.dr),
                num(bl.i2),
                tex(bl.i1),
                num(bl.value),
                num(bl.value.round())
            ),
        )
        .value("bilinear", bl.value)
        .value("weights", Value::numbers(&bl.weights())),
    );
    match &bc {
        Some(b) => {
            let (bc0, br0) = (fc + b.c as f64, fr + b.r as f64);
            let p: Vec<Vec<f64>> = b.p.iter().map(|r| r.to_vec()).collect();
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
                .formula(
                    r"f(x) = \begin{cases} (a+2)|x|^3 - (a+3)|x|^2 + 1 & |x| < 1 \\ a|x|^3 - 5a|x|^2 + 8a|x| - 4a & 1 \le |x| < 2 \\ 0 & 2 \le |x| \end{cases}",
                    format!(
                        r"a = {},\ s = {}:\ [f(1+s),\,f(s),\,f(1-s),\,f(2-s)] = [{}],\quad t = {}:\ [f(1+t),\,f(t),\,f(1-t),\,f(2-t)] = [{}]",
                        tex(b.a),
                        num(b.s),
                        b.wc.iter().map(|x| num(*x)).collect::<Vec<_>>().join(",\\,"),
                        num(b.t),
                        b.wr.iter().map(|x| num(*x)).collect::<Vec<_>>().join(",\\,"),
                    ),
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
                .formula(
                    r"Q = [f(1+t)\ f(t)\ f(1-t)\ f(2-t)]\; P \;[f(1+s)\ f(s)\ f(1-s)\ f(2-s)]^T",
                    format!(
                        r"P = {},\quad P\,w_c = [{}]^T,\quad Q = {}",
                        bmatrix(&p),
                        b.rows.iter().map(|x| num(*x)).collect::<Vec<_>>().join(",\\,"),
                        num(b.value)
                    ),
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
    for (k, l, u) in [
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
    ] {
        s.label(k, l, u);
    }
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
