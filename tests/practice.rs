//! Practice mode: the 10 000-seed audit of every generator, and grading of
//! correct, rounded-as-shown, carried-forward and named-mistake answers on
//! fixed variants.

use photogrammetry_playground::examples::{self, fields::Field};
use photogrammetry_playground::practice::{
    self, encode, grade, inputs_of, practice as variant, specs, value_in, Spec,
};
use photogrammetry_playground::solution::{Record, Value};

const SEEDS: u32 = 10_000;

/// The givens as the page prints them (`Field::format`) read back exactly.
fn printed_roundtrip(fields: &[Field], inputs: &Record) -> Record {
    let mut out = Record::new();
    for (k, v) in inputs.iter() {
        let f = fields
            .iter()
            .find(|f| f.key == k)
            .expect("generated key is a field");
        let text = f.format(v);
        out.set(k, f.parse_text(&text).expect("printed given reads back"));
    }
    out
}

fn fields_of(id: &str) -> Vec<Field> {
    (examples::entries()
        .into_iter()
        .find(|e| e.id == id)
        .expect("spec id in catalog")
        .fields)()
}

fn audit(spec: &Spec, seeds: u32) {
    let fields = fields_of(spec.id);
    for v in 0..seeds {
        let inputs = inputs_of(spec, v);
        let code = encode(v);
        let s = examples::solve(spec.id, &inputs)
            .unwrap_or_else(|e| panic!("{} {code}: solve failed: {e}", spec.id));
        let printed = printed_roundtrip(&fields, &inputs);
        assert_eq!(
            printed, inputs,
            "{} {code}: givens change when printed",
            spec.id
        );
        let boxes = (spec.boxes)(&inputs);
        assert!(!boxes.is_empty());
        let chained = spec
            .chain
            .map(|c| c(&inputs, &Record::new()).expect("chain runs"));
        for b in &boxes {
            let x = value_in(&s, &b.key).unwrap_or_else(|e| panic!("{} {code}: {e}", spec.id));
            assert!(
                x.is_finite() && x.abs() < 1e6,
                "{} {code}: box {} = {x} is not a number a student can handle",
                spec.id,
                b.key
            );
            if let Some(ch) = &chained {
                let y = ch.number(&b.key).expect("chain has every box");
                assert!(
                    (x - y).abs() <= 1e-9 * (1.0 + x.abs()),
                    "{} {code}: chain gives {y} for {}, the solver {x}",
                    spec.id,
                    b.key
                );
            }
        }
        // Every named mistake belongs to a box and is a number.
        for m in (spec.mistakes)(&inputs).expect("mistakes compute") {
            assert!(
                boxes.iter().any(|b| b.key == m.key),
                "{}: {}",
                spec.id,
                m.key
            );
            assert!(
                m.value.is_finite(),
                "{} {code}: {} not finite",
                spec.id,
                m.name
            );
        }
        well_posed(spec.id, &code, &s);
    }
}

fn num(s: &Record, key: &str) -> f64 {
    s.number(key).unwrap_or(f64::NAN)
}

/// The example-specific signs of a good variant.
fn well_posed(id: &str, code: &str, s: &photogrammetry_playground::solution::Solution) {
    let r = &s.result;
    let fail = |why: &str| panic!("{id} {code}: {why}");
    match id {
        "pixel-to-photo" => {
            if num(r, "x_px") == 0.0 || num(r, "y_px") == 0.0 {
                fail("the point is on an axis")
            }
        }
        "photo-to-pixel" => {
            let (c, rr) = (num(r, "c"), num(r, "r"));
            let (w, h) = (num(&s.inputs, "columns"), num(&s.inputs, "rows"));
            if !(c > 0.0 && c < w && rr > 0.0 && rr < h) {
                fail("the point is outside the image")
            }
        }
        _ => {}
    }
}

/// The whole audit of one example, or a sample of `SEEDS` when asked for.
macro_rules! audit_tests {
    ($($name:ident => $id:literal),* $(,)?) => {$(
        #[test]
        fn $name() {
            let spec = specs().into_iter().find(|s| s.id == $id).expect("spec");
            audit(&spec, SEEDS);
        }
    )*};
}

audit_tests! {
    audit_pixel_to_photo => "pixel-to-photo",
    audit_gsd => "gsd",
    audit_photo_to_pixel => "photo-to-pixel",
}

#[test]
fn every_ready_example_but_utm_has_practice() {
    let have: Vec<_> = specs().iter().map(|s| s.id).collect();
    let missing: Vec<_> = examples::catalog()
        .into_iter()
        .filter(|e| e.status == "ready" && !have.contains(&e.id))
        .map(|e| e.id)
        .collect();
    assert_eq!(missing, Vec::<&str>::new());
}

/// Answers from `(key, text)` pairs.
fn answers(pairs: &[(&str, &str)]) -> Record {
    let mut r = Record::new();
    for (k, t) in pairs {
        r.set(k, Value::Text(t.to_string()));
    }
    r
}

/// The exact value of box `key` in variant `code`.
fn exact(id: &str, code: &str, key: &str) -> f64 {
    let p = variant(id, Some(code), 0).unwrap();
    let s = examples::solve(id, &p.inputs).unwrap();
    value_in(&s, key).unwrap()
}

fn verdict(g: &practice::Graded, key: &str) -> String {
    let b = g.get(key).unwrap();
    format!("{:?}", b.verdict).to_lowercase()
}
