//! Lecture 21: least-squares matching with an affine geometric model and gain and offset, on a generated patch pair or on two given patches.

use super::*;

pub(super) fn lsm_affine(inputs: &Record) -> Result<Solution> {
    let mut s = Solution::new(
        "lsm-affine",
        "Affine + radiometric least-squares matching",
        inputs.clone(),
    );
    let set = settings(Model::AffineRadiometric, Gradients::SearchWindow, inputs)?;
    let given = text(inputs, "pair")? == "patches";
    let pair = if given {
        given_pair(&mut s, inputs)?
    } else {
        generated_pair(&mut s, inputs)?
    };
    let Pair {
        template,
        search,
        start,
        origin,
        truth,
        noise,
    } = pair;
    let m = matching::match_2d(&template, &search, start, set).map_err(|e| {
        if given {
            said_of(e, "c0")
        } else {
            e
        }
    })?;
    let syms = symbols(&m.estimated, false);
    s.step(
        Step::new(
            "Observation equation and initial values (Lecture 21)",
            if given {
                "One equation per template pixel, linearised at the current parameters; G_p, G_q are the central-difference gradients of the resampled search patch along the window's columns and rows. Initial values as Lecture 21 says, with the translations at the start position: the diagonal of the affine part 1, gain 1, offset 0."
            } else {
                "One equation per template pixel, linearised at the current parameters; G_p, G_q are the central-difference gradients of the resampled search patch along the window's columns and rows. Initial values as Lecture 21 says: translations zero, the diagonal of the affine part 1, gain 1, offset 0."
            },
        )
        .formula(
            r"T - (a_7 G + a_8) + V = a_7G_p(u\,da_1 + v\,da_2 + da_3) + a_7G_q(u\,da_4 + v\,da_5 + da_6) + G\,da_7 + da_8",
            format!(
                r"\mathbf{{a}}^0 = [1, 0, {}, 0, 1, {}, 1, 0]",
                num(start.a[2] - origin),
                num(start.a[5] - origin)
            ),
        ),
    );
    if let Some(it) = m.iterations.first() {
        s.step(
            Step::new(
                "Design matrix and normal equations (iteration 1)",
                "A has one row per template pixel and eight columns; N = AᵀA is 8×8.",
            )
            .formula(
                r"A_i = [a_7G_p u,\ a_7G_p v,\ a_7G_p,\ a_7G_q u,\ a_7G_q v,\ a_7G_q,\ G,\ 1]",
                format!(
                    r"A_1 = {},\quad N = {},\quad d\mathbf{{X}} = {}",
                    numeric(&it.a.iter().take(1).cloned().collect::<Vec<_>>()),
                    numeric(&it.adjustment.n),
                    column(&it.increments)
                ),
            )
            .value("A", Value::matrix(&it.a))
            .value("N", Value::matrix(&it.adjustment.n))
            .value("increments", Value::numbers(&it.increments)),
        );
    }
    s.step(table_step(&m, &syms, origin));
    status_step(&mut s, &m, &syms, set.max_iterations);

    let est: Vec<f64> = (0..8)
        .map(|k| {
            let x = m.params.a.get(k).copied().unwrap_or(0.0);
            if k == 2 || k == 5 {
                x - origin
            } else {
                x
            }
        })
        .collect();
    let sd = m.std_dev();
    let sd_text = |k: usize| {
        sd.as_ref()
            .and_then(|v| v.get(k))
            .map_or("–".to_string(), |x| fmt_sig(*x, 3))
    };
    let est_text = |k: usize| num(est.get(k).copied().unwrap_or(0.0));
    let rows: Vec<String> = (0..8)
        .map(|k| match &truth {
            Some(t) => format!(
                r"a_{} & {} & {} & {}",
                k + 1,
                num(t.a.get(k).copied().unwrap_or(0.0)),
                est_text(k),
                sd_text(k)
            ),
            None => format!(r"a_{} & {} & {}", k + 1, est_text(k), sd_text(k)),
        })
        .collect();
    let (title, table) = match &truth {
        Some(_) => (
            "Estimates beside the truth",
            format!(
                r"\begin{{array}}{{l|rrr}} & \text{{true}} & \text{{estimate}} & \sigma \\ \hline {} \end{{array}}",
                rows.join(r" \\ ")
            ),
        ),
        None => (
            "Estimates",
            format!(
                r"\begin{{array}}{{l|rr}} & \text{{estimate}} & \sigma \\ \hline {} \end{{array}}",
                rows.join(r" \\ ")
            ),
        ),
    };
    let how = if given {
        "a3 and a6 are the column and row of the template's centre in the search window, counted from 1. The standard deviations are σ0·√qᵢᵢ from the last iteration's Qxx = N⁻¹."
    } else {
        "The standard deviations are σ0·√qᵢᵢ from the last iteration's Qxx = N⁻¹."
    };
    let true_parameters = truth.as_ref().map_or(Value::Null, |t| Value::numbers(&t.a));
    let mut step = Step::new(title, how)
        .formula(r"\sigma_{a_j} = \sigma_0\sqrt{q_{jj}}", table)
        .value("parameters", Value::numbers(&est))
        .value("true_parameters", true_parameters.clone())
        // the scale and rotation the estimate implies (no shear: the first
        // column of [a1 a2; a4 a5] is s·(cos θ, sin θ))
        .value("estimated_scale", est[0].hypot(est[3]))
        .value("estimated_rotation_deg", est[3].atan2(est[0]).to_degrees());
    if let Some(sd) = &sd {
        step = step.value("std_dev", Value::numbers(sd));
    }
    s.step(step);
    // the noise the residuals should show: template noise plus the search
    // noise carried through the bilinear weights and the gain
    let expected = if noise > 0.0 {
        let m2 = mean_square_weights(&template, &m.params);
        let e = noise * (1.0 + m.params.gain().powi(2) * m2).sqrt();
        s.step(
            Step::new(
                "σ0 against the noise",
                "Each residual carries the template's noise and the search window's noise, the latter through the four bilinear weights w_k and the gain; averaged over the patch this is what σ0 should come out as.",
            )
            .formula(
                r"\sigma_0 \approx \sigma_n\sqrt{1 + a_7^2\,\overline{\textstyle\sum_k w_k^2}}",
                format!(
                    r"\sigma_0 = {},\quad \sigma_n\sqrt{{1 + a_7^2\,\overline{{\textstyle\sum_k w_k^2}}}} = {}\sqrt{{1 + {}^2 \times {}}} = {}",
                    m.sigma0().map_or("–".to_string(), num),
                    num(noise),
                    num(m.params.gain()),
                    num(m2),
                    num(e)
                ),
            )
            .value("expected_sigma0", e),
        );
        Some(e)
    } else {
        None
    };
    s.result = Record::new()
        .with("parameters", Value::numbers(&est))
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("sigma0", m.sigma0())
        .with("true_parameters", true_parameters)
        .with(
            "std_dev",
            sd.as_ref().map_or(Value::Null, |v| Value::numbers(v)),
        )
        .with("status", m.status.word())
        .with("expected_sigma0", expected);
    s.note(
        NoteKind::Convention,
        "Lecture 21 writes the affine and the radiometric parts as two stacked systems of 2m rows with zero blocks (its second block's unknowns are misprinted as Δa5 … Δa8). Both parts describe the same grey values, so here they form one observation per pixel, T = a7·S(p, q) + a8, with all eight unknowns in one m × 8 design matrix — the formulation of worked examples 10–11.",
    ).about(&["parameters"]);
    if given {
        s.note(
            NoteKind::Convention,
            "Columns c (to the right) and rows r (downward) count from 1 as in the course notes: the estimates a3, a6 are the search-window position of the template's centre pixel.",
        )
        .about(&["parameters"]);
    } else {
        s.note(
            NoteKind::Convention,
            "The template is made from the search window with the same bilinear interpolation the matching uses, so without noise the model fits exactly and the estimates return the true values. Real images also carry the interpolation's own error: for a template sampled from a smooth continuous texture instead, the least-squares optimum itself lies up to about 0.1 px from the true shift (measured in this project's tests).",
        ).about(&["parameters", "sigma0"]);
    }
    if m.converged() {
        if let (Some(sd), Some(truth)) = (&sd, &truth) {
            let off: Vec<String> = (0..8)
                .filter(|&k| {
                    let d = (est.get(k).copied().unwrap_or(0.0)
                        - truth.a.get(k).copied().unwrap_or(0.0))
                    .abs();
                    d > 5.0 * sd.get(k).copied().unwrap_or(0.0) + 1e-3
                })
                .map(|k| format!("a{}", k + 1))
                .collect();
            if !off.is_empty() {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The run converged, but {} lie more than five standard deviations from the truth: it found another optimum. The start (identity, zero shift) is outside the pull-in range for this transformation.",
                        off.join(", ")
                    ),
                ).about(&["parameters"]);
            }
        }
    }
    label_results(&mut s);
    Ok(s)
}

/// The pair `lsm-affine` matches, its start, the origin its shifts count
/// from (the search window's centre, or −1 for 1-based positions), and the
/// truth when it is known.
struct Pair {
    template: Grid,
    search: Grid,
    start: Params,
    origin: f64,
    truth: Option<Params>,
    noise: f64,
}

/// Seed 003's generated pair: a texture seen through a known affine and
/// radiometric change, started at the identity with zero shift.
fn generated_pair(s: &mut Solution, inputs: &Record) -> Result<Pair> {
    let i = Inputs(inputs);
    let size = i.number("patch_size")?;
    if size.rem_euclid(2.0) != 1.0 {
        return Err(Error::input(
            "patch_size",
            format!("must be odd, so that the template has a centre pixel (got {size})"),
        ));
    }
    let truth = matching::affine_from(
        i.number("shift_c")?,
        i.number("shift_r")?,
        i.number("rotation_deg")?,
        i.number("scale")?,
        i.number("shear")?,
        i.number("gain")?,
        i.number("offset")?,
    );
    let noise = i.number("noise")?;
    let seed = i.number("seed")?;
    let pair = matching::synthetic_pair(size as usize, &truth, noise, seed as u64)?;
    let a = &truth.a;
    s.step(
        Step::new(
            "The generated pair",
            "A smooth texture (six sinusoids, wavelengths 7–16 px, drawn with the random seed) fills the search window. The template is that window seen through the chosen transformation — resampled bilinearly at p = a1·u + a2·v + a3, q = a4·u + a5·v + a6 — then scaled by the gain and shifted by the offset; noise is added to both. u, v count from the template's centre, p, q from the search window's centre.",
        )
        .formula(
            r"\begin{bmatrix} a_1 & a_2 \\ a_4 & a_5 \end{bmatrix} = s\begin{bmatrix} \cos\theta & -\sin\theta \\ \sin\theta & \cos\theta \end{bmatrix}\begin{bmatrix} 1 & k \\ 0 & 1 \end{bmatrix},\quad T(u,v) = a_7\,S(p,q) + a_8 + n",
            format!(
                r"\begin{{bmatrix}} a_1 & a_2 \\ a_4 & a_5 \end{{bmatrix}} = {},\quad \begin{{bmatrix}} a_3 \\ a_6 \end{{bmatrix}} = {},\quad a_7 = {},\ a_8 = {},\ \sigma_n = {}",
                numeric(&[vec![a[0], a[1]], vec![a[3], a[4]]]),
                column(&[a[2], a[5]]),
                num(a[6]),
                num(a[7]),
                num(noise)
            ),
        )
        .value("template", Value::matrix(&pair.template.rows()))
        .value("search", Value::matrix(&pair.search.rows()))
        .value("true_parameters", Value::numbers(&truth.a)),
    );
    Ok(Pair {
        start: Params::shift(pair.centre, pair.centre, 1.0, 0.0),
        origin: pair.centre,
        template: pair.template,
        search: pair.search,
        truth: Some(truth),
        noise,
    })
}

/// A given template and search window (as the image lab cuts them from a
/// photo), started at (c⁰, r⁰) with the identity, gain 1 and offset 0;
/// positions count from 1.
fn given_pair(s: &mut Solution, inputs: &Record) -> Result<Pair> {
    let Patches {
        tr,
        sr,
        template,
        search,
    } = patches(inputs)?;
    let i = Inputs(inputs);
    let (c0, r0) = (i.number("c0")?, i.number("r0")?);
    s.step(
        Step::new(
            "Template, search window and start",
            "The template's centre is placed at (c⁰, r⁰) in the search window, columns c to the right and rows r downward, both counted from 1; u, v count from the template's centre.",
        )
        .formula(
            r"T,\ S,\quad (c^0, r^0)",
            format!(
                r"T = {},\quad (c^0, r^0) = ({}, {})",
                numeric(&tr),
                num(c0),
                num(r0)
            ),
        )
        .value("template", Value::matrix(&tr))
        .value("search", Value::matrix(&sr)),
    );
    Ok(Pair {
        template,
        search,
        start: Params::shift(c0 - 1.0, r0 - 1.0, 1.0, 0.0),
        origin: -1.0,
        truth: None,
        noise: 0.0,
    })
}

/// Mean over the template pixels of Σ w_k² of the four bilinear weights at
/// the parameters' positions.
pub(super) fn mean_square_weights(t: &Grid, p: &Params) -> f64 {
    let (w, h) = (t.width(), t.height());
    let (cu, cv) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
    let mut sum = 0.0;
    for j in 0..h {
        for i in 0..w {
            let (c, r) = p.map(i as f64 - cu, j as f64 - cv);
            let (fc, fr) = (c - c.floor(), r - r.floor());
            sum += ((1.0 - fc).powi(2) + fc * fc) * ((1.0 - fr).powi(2) + fr * fr);
        }
    }
    sum / (w * h).max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers_of(s: &Solution, key: &str) -> Vec<f64> {
        match s.result.get(key) {
            Some(Value::List(xs)) => xs.iter().filter_map(Value::as_f64).collect(),
            other => panic!("{key}: {other:?}"),
        }
    }

    fn step_matrix(s: &Solution, key: &str) -> Value {
        s.steps
            .iter()
            .find_map(|st| st.values.get(key).cloned())
            .unwrap_or_else(|| panic!("{key}: in no step"))
    }

    #[test]
    fn given_patches_match_as_the_generated_pair_does() {
        // the generated pair, handed over as given patches with the same start
        let g = crate::examples::solve("lsm-affine", &Record::new()).unwrap();
        let search = step_matrix(&g, "search");
        let n = match &search {
            Value::List(rows) => rows.len() as f64,
            _ => panic!("search"),
        };
        let origin = (n - 1.0) / 2.0;
        let inputs = Record::new()
            .with("pair", "patches")
            .with("template", step_matrix(&g, "template"))
            .with("search", search)
            .with("c0", origin + 1.0)
            .with("r0", origin + 1.0);
        let p = crate::examples::solve("lsm-affine", &inputs).unwrap();
        let (eg, ep) = (numbers_of(&g, "parameters"), numbers_of(&p, "parameters"));
        for k in 0..8 {
            // a3, a6: from the window's centre there, 1-based positions here
            let shift = if k == 2 || k == 5 { origin + 1.0 } else { 0.0 };
            assert!(
                (ep[k] - (eg[k] + shift)).abs() < 1e-9,
                "a{}: {ep:?} vs {eg:?}",
                k + 1
            );
        }
        assert_eq!(p.result.get("true_parameters"), Some(&Value::Null));
        assert_eq!(p.result.get("converged"), Some(&Value::Bool(true)));
        // the default given pair: 4°, 1.05, centre (6.3, 5.8) within the
        // rounding of its grey values to integers
        let d =
            crate::examples::solve("lsm-affine", &Record::new().with("pair", "patches")).unwrap();
        let e = numbers_of(&d, "parameters");
        let (sn, cs) = 4f64.to_radians().sin_cos();
        assert!(
            (e[0] - 1.05 * cs).abs() < 0.02 && (e[3] - 1.05 * sn).abs() < 0.02,
            "{e:?}"
        );
        assert!(
            (e[2] - 6.3).abs() < 0.05 && (e[5] - 5.8).abs() < 0.05,
            "{e:?}"
        );
        assert!(
            (e[6] - 1.1).abs() < 0.05 && (e[7] + 5.0).abs() < 5.0,
            "{e:?}"
        );
    }

    #[test]
    fn lsm_2d_without_radiometry_estimates_the_shift_only() {
        let s = crate::examples::solve(
            "lsm-2d",
            &Record::new().with("radiometric", false).with("b0", 0.0),
        )
        .unwrap();
        let t = Grid::from_rows("template", &ex7_template()).unwrap();
        let sw = Grid::from_rows("search", &ex7_search()).unwrap();
        let m = matching::match_2d(
            &t,
            &sw,
            Params::shift(2.0, 3.0, 1.0, 0.0),
            Settings {
                model: Model::Shift,
                gradients: Gradients::SearchWindow,
                max_iterations: matching::DEFAULT_ITERATIONS,
            },
        )
        .unwrap();
        assert_eq!(s.result.get("c"), Some(&Value::Number(m.params.a[2] + 1.0)));
        assert_eq!(s.result.get("r"), Some(&Value::Number(m.params.a[5] + 1.0)));
        assert_eq!(s.result.get("a"), Some(&Value::Number(1.0)));
        assert_eq!(s.result.get("b"), Some(&Value::Number(0.0)));
        assert_eq!(s.result.get("first_da"), Some(&Value::Null));
    }
}
