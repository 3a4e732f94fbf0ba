//! The lab's wasm boundary in headless Chromium: decoding (good and bad
//! files) and one operator of each family, as the worker calls them.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Float32Array, Float64Array, Reflect};
use photogrammetry_lab::wasm::*;
use photogrammetry_playground::interest;
use photogrammetry_playground::raster::Grid;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn layer(v: &JsValue, i: u32) -> JsValue {
    Array::from(v).get(i)
}

/// A layer's values (a `Float32Array`) as numbers.
fn data(l: &JsValue) -> Vec<f64> {
    let v = get(l, "data");
    assert!(
        v.is_instance_of::<Float32Array>(),
        "layers are Float32Arrays"
    );
    Float32Array::from(v)
        .to_vec()
        .into_iter()
        .map(f64::from)
        .collect()
}

fn message(e: wasm_bindgen::JsError) -> String {
    let v: JsValue = e.into();
    js_sys::Error::from(v).message().into()
}

const GREY8: &[u8] = include_bytes!("corpus/grey8.png");
const GREY16: &[u8] = include_bytes!("corpus/grey16.png");
const TIFF16: &[u8] = include_bytes!("corpus/grey16_strips.tif");
const JPEG: &[u8] = include_bytes!("corpus/blocks.jpg");

#[wasm_bindgen_test]
fn decodes_known_pixels_across_the_boundary() {
    let img = decode_image("grey8.png".into(), GREY8).unwrap();
    assert_eq!((img.width(), img.height(), img.bits()), (4, 3, 8));
    assert_eq!(
        img.grey().to_vec(),
        (0..12)
            .map(|i| (10 * (i % 4) + 40 * (i / 4)) as f64)
            .collect::<Vec<_>>()
    );
    let img = decode_image("grey16.png".into(), GREY16).unwrap();
    assert_eq!(img.value(3, 2), Some(43007.0));
    assert_eq!(img.max_value(), 65535.0);
    let img = decode_image("grey16_strips.tif".into(), TIFF16).unwrap();
    assert_eq!(
        (img.format(), img.value(3, 2)),
        ("TIFF".to_string(), Some(43007.0))
    );
    let img = decode_image("blocks.jpg".into(), JPEG).unwrap();
    assert_eq!(
        (img.value(0, 0), img.value(15, 7)),
        (Some(50.0), Some(200.0))
    );
}

#[wasm_bindgen_test]
fn bad_files_throw_errors_naming_the_file() {
    for (name, bytes, says) in [
        (
            "empty.png",
            &include_bytes!("corpus/empty.png")[..],
            "empty",
        ),
        (
            "text.png",
            &include_bytes!("corpus/text.png")[..],
            "not a PNG",
        ),
        (
            "bad_crc.png",
            &include_bytes!("corpus/bad_crc.png")[..],
            "damaged",
        ),
        (
            "huge_header.png",
            &include_bytes!("corpus/huge_header.png")[..],
            "too large",
        ),
        (
            "bomb.png",
            &include_bytes!("corpus/bomb.png")[..],
            "megapixels",
        ),
        (
            "truncated.jpg",
            &include_bytes!("corpus/truncated.jpg")[..],
            "cut short",
        ),
        (
            "missing_tag.tif",
            &include_bytes!("corpus/missing_tag.tif")[..],
            "TIFF",
        ),
        (
            "truncated.png",
            &include_bytes!("corpus/truncated.png")[..],
            "PNG",
        ),
        (
            "zero_width.png",
            &include_bytes!("corpus/zero_width.png")[..],
            "PNG",
        ),
        (
            "unsupported.qoi",
            &include_bytes!("corpus/unsupported.qoi")[..],
            "is a QOI image, a format the lab does not read",
        ),
    ] {
        let m = message(decode_image(name.into(), bytes).err().expect(name));
        assert!(
            m.starts_with(&format!("{name}: ")) && m.contains(says),
            "{m}"
        );
    }
    // and the module keeps working
    assert!(decode_image("grey8.png".into(), GREY8).is_ok());
}

#[wasm_bindgen_test]
fn one_operator_of_each_family_across_the_boundary() {
    let img = decode_image("grey8.png".into(), GREY8).unwrap();
    // filter: the 3×3 mean at (1, 1) of g = 10c + 40r is g(1, 1) = 50
    let out = run_filter(&img, "mean".into(), "crop".into(), JsValue::UNDEFINED, None).unwrap();
    let l = layer(&out, 0);
    assert_eq!(get(&l, "c0").as_f64(), Some(1.0));
    assert!((data(&l)[0] - 50.0).abs() < 1e-12);
    // edges: Sobel gx (top minus bottom, weights 1 2 1) of a ramp rising 40 a
    // row is 4·(−80) = −320; gy (right minus left) 4·20 = 80
    let out = run_edges(&img, "sobel".into(), "crop".into()).unwrap();
    assert!((data(&layer(&out, 0))[0] + 320.0).abs() < 1e-12);
    assert!((data(&layer(&out, 1))[0] - 80.0).abs() < 1e-12);
    // interest: Moravec on a textured checkerboard (below)
    moravec_points_are_the_window_means_kept_by_the_rule();
    let frame = scanned_frame();
    // correlation: a template found in its own image with ρ = 1
    let t = [40.0, 490.0, 21.0, 21.0];
    let s = [30.0, 480.0, 41.0, 41.0];
    let out = run_correlation(&frame, &t, &frame, &s, "shift".into()).unwrap();
    let best = Float64Array::from(get(&out, "best")).to_vec();
    assert_eq!(best, vec![50.0, 500.0]);
    // resampling: scale 1, angle 0 reproduces the image by all three methods
    let out = run_resample(&img, "rotate".into(), &[0.0, 1.0], 4, 3, None, None).unwrap();
    assert_eq!(data(&layer(&out, 0)), img.grey().to_vec());
    // boundaries: the whole 4×3 image above −1 is one region of 12 pixels
    let out = run_boundary(&img, -1.0, 0, 0).unwrap();
    assert_eq!(get(&out, "area").as_f64(), Some(12.0));
    assert_eq!(get(&out, "code").as_string().unwrap(), "1117755533");
    // fiducials: the four marks of the generated frame
    let truth = scanned_frame_truth().unwrap();
    let nominal = Float64Array::from(get(&truth, "nominal")).to_vec();
    let out = run_fiducials(&frame, &nominal).unwrap();
    let marks = Float64Array::from(get(&out, "marks")).to_vec();
    let true_marks = Float64Array::from(get(&truth, "marks")).to_vec();
    for k in 0..4 {
        let d = (marks[4 * k] - true_marks[2 * k]).hypot(marks[4 * k + 1] - true_marks[2 * k + 1]);
        assert!(d < 0.1, "mark {k}: {d} px");
    }
    // a bad parameter is an Error naming the field
    let m = message(
        run_filter(&img, "blur".into(), "crop".into(), JsValue::UNDEFINED, None)
            .err()
            .unwrap(),
    );
    assert!(m.starts_with("kernel: "), "{m}");
    let m = message(
        run_correlation(&frame, &[0.0, 0.0, 4.0, 4.0], &frame, &s, "shift".into())
            .err()
            .unwrap(),
    );
    assert!(m.starts_with("template: "), "{m}");
}

/// A 64 × 48 checkerboard of 8-pixel squares with a texture.
fn checkerboard() -> Vec<u8> {
    (0..64 * 48)
        .map(|i| {
            let (c, r) = (i % 64, i / 64);
            (if ((c / 8) + (r / 8)) % 2 == 1 {
                200
            } else {
                50
            } + (c * 7 + r * 13) % 17) as u8
        })
        .collect()
}

/// Moravec across the boundary: every point's value is the core's
/// `moravec` mean of its 4 × 4 window (moravec-window's `mean`), above the
/// threshold, and the points are exactly the cells above the threshold with
/// no larger value within ±2 cells (ties: the first in row-major order),
/// worked out here from the layer.
fn moravec_points_are_the_window_means_kept_by_the_rule() {
    let bytes = checkerboard();
    let img = image_from_u8(64, 48, &bytes).unwrap();
    let grid = Grid::new(
        "image",
        64,
        48,
        bytes.iter().map(|&b| f64::from(b)).collect(),
    )
    .unwrap();
    let threshold = 2000.0;
    let out = run_moravec(&img, 4, threshold).unwrap();
    let l = layer(&get(&out, "layers"), 0);
    let (w, h) = (
        get(&l, "width").as_f64().unwrap() as usize,
        get(&l, "height").as_f64().unwrap() as usize,
    );
    let (c0, r0) = (
        get(&l, "c0").as_f64().unwrap() as usize,
        get(&l, "r0").as_f64().unwrap() as usize,
    );
    let map = data(&l);
    let at = |c: usize, r: usize| -> Option<f64> {
        (c >= c0 && r >= r0 && c < c0 + w && r < r0 + h)
            .then(|| map[(r - r0) * w + c - c0])
            .filter(|v| v.is_finite())
    };
    // the layer is the window means at every pixel that has a window
    let mut cells = 0;
    for r in 0..48 {
        for c in 0..64 {
            let want = interest::window_at(&grid, c, r, 4)
                .map(|win| interest::moravec(&win).unwrap().mean);
            // (the means of 2 × 2 sums are exact in the layer's f32)
            assert_eq!(at(c, r), want, "({c}, {r})");
            cells += usize::from(want.is_some());
        }
    }
    assert!(cells > 40 * 60, "{cells}");
    let pts = Float64Array::from(get(&out, "points")).to_vec();
    let got: Vec<(usize, usize, f64)> = pts
        .chunks(6)
        .map(|p| (p[0] as usize, p[1] as usize, p[2]))
        .collect();
    let mut want = Vec::new();
    for r in 0..48usize {
        for c in 0..64usize {
            let Some(v) = at(c, r).filter(|&v| v > threshold) else {
                continue;
            };
            let beaten = (r.saturating_sub(2)..=(r + 2).min(47)).any(|rr| {
                (c.saturating_sub(2)..=(c + 2).min(63)).any(|cc| {
                    at(cc, rr)
                        .filter(|&x| x > threshold)
                        .is_some_and(|x| x > v || (x == v && (rr, cc) < (r, c)))
                })
            });
            if !beaten {
                want.push((c, r, v));
            }
        }
    }
    assert!(want.len() >= 10, "{} points", want.len());
    assert_eq!(got, want);
    for (c, r, v) in got {
        let win = interest::window_at(&grid, c, r, 4).unwrap();
        assert_eq!(interest::moravec(&win).unwrap().mean, v);
    }
}

#[wasm_bindgen_test]
fn a_custom_kernel_and_a_kept_forstner_map_across_the_boundary() {
    let img = decode_image("grey8.png".into(), GREY8).unwrap();
    // [1 2 1] normalised (÷4) along a row of g = 10c + 40r: g itself inside
    let out = run_filter(&img, "custom".into(), "crop".into(), "1, 2, 1".into(), None).unwrap();
    let l = layer(&out, 0);
    assert_eq!(get(&l, "name").as_string().unwrap(), "custom");
    assert_eq!(data(&l)[0], 10.0);
    // the same kernel with divisor 1: four times that
    let out = run_filter(
        &img,
        "custom".into(),
        "crop".into(),
        "1 2 1".into(),
        Some(1.0),
    )
    .unwrap();
    assert_eq!(data(&layer(&out, 0))[0], 40.0);
    let checked = check_custom_kernel("1 2 1\n2 4 2\n1 2 1".into(), None).unwrap();
    assert_eq!(get(&checked, "divisor").as_f64(), Some(16.0));
    for (text, d, says) in [
        ("1 2 x", None, "custom_kernel: row 1: \"x\" is not a number"),
        ("1 2 1; 1 2", None, "custom_kernel: row 2 has 2 numbers"),
        ("1 1", None, "custom_kernel: is 1×2"),
        ("-1 0 1", None, "custom_divisor: the weights sum to 0"),
        ("1 2 1", Some(0.0), "custom_divisor: must be"),
    ] {
        let m = message(
            run_filter(&img, "custom".into(), "crop".into(), text.into(), d)
                .err()
                .unwrap(),
        );
        assert!(m.starts_with(says), "{m}");
    }
    let m = message(
        run_filter(
            &img,
            "custom".into(),
            "crop".into(),
            JsValue::UNDEFINED,
            None,
        )
        .err()
        .unwrap(),
    );
    assert!(m.starts_with("custom_kernel: is missing"), "{m}");
    // Förstner: the kept map's points for a threshold equal a full run's
    // (a 64 × 48 checkerboard of 8-pixel squares with a texture)
    let bytes = checkerboard();
    let frame = image_from_u8(64, 48, &bytes).unwrap();
    let mut maps = forstner_maps(&frame, 5).unwrap();
    assert_eq!(maps.size(), 5);
    for t in [0.3, 1.0] {
        let full = run_forstner(&frame, 5, 8.0, t, 0.5).unwrap();
        let want = Float64Array::from(get(&full, "points")).to_vec();
        let got = Float64Array::from(maps.points(8.0, t, 0.5).unwrap()).to_vec();
        assert_eq!(got, want, "T = {t}");
    }
    let w = data(&layer(&maps.layers().unwrap(), 0));
    assert_eq!(w.len(), 64 * 48);
    assert!(Float64Array::from(maps.points(8.0, 1.0, 0.5).unwrap()).length() >= 6 * 20);
    let m = message(maps.points(8.0, -1.0, 0.5).err().unwrap());
    assert!(m.starts_with("threshold_px: "), "{m}");
}

#[wasm_bindgen_test]
fn the_students_fiducial_clicks_are_refined_and_fitted() {
    let frame = scanned_frame();
    let truth = scanned_frame_truth().unwrap();
    let true_marks = Float64Array::from(get(&truth, "marks")).to_vec();
    // clicks 3 px off each true mark are refined onto it
    let mut measured = Vec::new();
    for k in 0..4 {
        let (c, r) = (true_marks[2 * k] + 3.0, true_marks[2 * k + 1] - 2.0);
        let m = refine_mark(&frame, c, r).unwrap().to_vec();
        let d = (m[0] - true_marks[2 * k]).hypot(m[1] - true_marks[2 * k + 1]);
        assert!(d < 0.1, "mark {k}: {d} px");
        measured.extend([m[0], m[1]]);
    }
    let fit = fit_fiducial_marks(&measured).unwrap();
    let p = Float64Array::from(get(&get(&fit, "affine"), "params")).to_vec();
    let t = Float64Array::from(get(&truth, "affine")).to_vec();
    for i in [0, 1, 3, 4] {
        assert!((p[i] - t[i]).abs() < 1e-4, "{p:?} vs {t:?}");
    }
    let res = Float64Array::from(get(&get(&fit, "similarity"), "residuals")).to_vec();
    assert_eq!(res.len(), 8);
    let m = message(refine_mark(&frame, -1.0, 5.0).err().unwrap());
    assert!(m.starts_with("mark: "), "{m}");
    let m = message(fit_fiducial_marks(&[1.0, 2.0]).err().unwrap());
    assert!(m.starts_with("marks: "), "{m}");
}

// ---------------------------------------------------------------- a trap

// A trap (wasm `unreachable`) aborts the instance it happens in: its Rust
// state (stack pointer, allocator, borrowed cells) may be left half-way, so
// the lab never calls into a trapped instance again but starts a fresh
// worker with a fresh instance. A trap inside this test's own instance would
// end the test run itself, so the test loads the same module (the runner's
// `wasm-bindgen-test.js` and its `.wasm`, served beside the page) as a
// second and a third instance through a dynamic import with a distinct
// query (a distinct module record, so a distinct instance), traps the
// second and shows the third decoding and filtering with known values.
#[wasm_bindgen(inline_js = r#"
export async function trap_then_fresh(png) {
  const glue = new URL("/wasm-bindgen-test.js", location.href).href;
  const wasm = new URL("/wasm-bindgen-test_bg.wasm", location.href).href;
  const instance = async (tag) => {
    const m = await import(`${glue}?instance=${tag}`);
    await m.default({ module_or_path: wasm });
    return m;
  };
  const a = await instance("trapped");
  let trapped = "";
  try {
    a.trap_for_tests();
  } catch (e) {
    trapped = `${e.constructor.name}: ${e.message}`;
  }
  const b = await instance("fresh");
  const img = b.decode_image("grey8.png", png);
  const out = b.run_filter(img, "mean", "crop", undefined, undefined);
  const layer = out[0];
  return { trapped, width: img.width(), height: img.height(), grey: Array.from(img.grey()), c0: layer.c0, mean: layer.data[0] };
}
"#)]
extern "C" {
    #[wasm_bindgen(catch)]
    fn trap_then_fresh(png: &[u8]) -> Result<js_sys::Promise, JsValue>;
}

#[wasm_bindgen_test]
async fn after_a_trap_a_fresh_instance_of_the_module_works() {
    let promise = trap_then_fresh(GREY8).expect("the helper starts");
    let out = wasm_bindgen_futures::JsFuture::from(promise)
        .await
        .expect("a fresh instance loads and runs");
    let trapped = get(&out, "trapped").as_string().unwrap();
    assert!(
        trapped.starts_with("RuntimeError: unreachable"),
        "{trapped}"
    );
    assert_eq!(get(&out, "width").as_f64(), Some(4.0));
    assert_eq!(get(&out, "height").as_f64(), Some(3.0));
    let grey: Vec<f64> = Array::from(&get(&out, "grey"))
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(
        grey,
        (0..12)
            .map(|i| (10 * (i % 4) + 40 * (i / 4)) as f64)
            .collect::<Vec<_>>()
    );
    // the 3×3 mean at (1, 1) of g = 10c + 40r is g(1, 1) = 50
    assert_eq!(get(&out, "c0").as_f64(), Some(1.0));
    assert!((get(&out, "mean").as_f64().unwrap() - 50.0).abs() < 1e-12);
    // and this test's own instance is untouched
    assert!(decode_image("grey8.png".into(), GREY8).is_ok());
}

/// An object `{ key: value, … }` for a request's arguments.
fn args(fields: &[(&str, JsValue)]) -> JsValue {
    let o = js_sys::Object::new();
    for (k, v) in fields {
        Reflect::set(&o, &JsValue::from_str(k), v).unwrap();
    }
    o.into()
}

// op_halo and exact_at: the halo a band needs from the request's own
// arguments, the exact (reference) number of one pixel; wrong arguments of
// every kind are errors naming the field, never traps.
#[wasm_bindgen_test]
fn halos_and_exact_values_across_the_boundary() {
    let filter = |k: &str| args(&[("kernel", k.into()), ("border", "crop".into())]);
    assert_eq!(
        op_halo("filter".into(), filter("gaussian-5")).unwrap(),
        Some(2)
    );
    assert_eq!(op_halo("filter".into(), filter("median")).unwrap(), Some(1));
    let custom = args(&[
        ("kernel", "custom".into()),
        ("border", "zero".into()),
        ("custom", "1 1 1;1 1 1;1 1 1;1 1 1;1 1 1".into()),
    ]);
    assert_eq!(op_halo("filter".into(), custom).unwrap(), Some(2));
    let edges = args(&[("operator", "sobel".into()), ("border", "crop".into())]);
    assert_eq!(op_halo("edges".into(), edges.clone()).unwrap(), Some(1));
    // Förstner 5×5: 2 rows below the anchor, plus the suppression's 2
    let size = |n: f64| args(&[("size", n.into())]);
    assert_eq!(op_halo("forstner".into(), size(5.0)).unwrap(), Some(4));
    assert_eq!(op_halo("moravec".into(), size(4.0)).unwrap(), Some(4));
    let rotate = args(&[
        ("kind", "rotate".into()),
        ("params", Array::of2(&0.0.into(), &1.0.into()).into()),
        ("width", 4.into()),
        ("height", 3.into()),
    ]);
    assert_eq!(op_halo("resample".into(), rotate.clone()).unwrap(), None);
    // exact values on g = 10c + 40r: the mean at (1, 1) is 50, Sobel gx −320
    let img = decode_image("grey8.png".into(), GREY8).unwrap();
    let at = |op: &str, a: JsValue, layer: &str, c, r| {
        exact_at(&img, &img, op.into(), a, layer.into(), c, r).unwrap()
    };
    assert_eq!(at("filter", filter("mean"), "mean", 1, 1), Some(50.0));
    assert_eq!(at("filter", filter("mean"), "mean", 0, 0), None);
    assert_eq!(at("edges", edges.clone(), "gx", 1, 1), Some(-320.0));
    assert_eq!(at("edges", edges.clone(), "gy", 1, 1), Some(80.0));
    // bicubic needs two pixels right of (2, 1): none there, 0 as the layer fills
    assert_eq!(at("resample", rotate.clone(), "bicubic", 2, 1), Some(0.0));
    assert_eq!(at("resample", rotate, "nearest", 2, 1), Some(60.0));
    for (kind, v) in every_kind() {
        for (name, r) in [
            ("op", op_halo(v.clone(), size(5.0)).map(|_| ())),
            (
                "op",
                exact_at(&img, &img, v.clone(), size(5.0), "w".into(), 1, 1).map(|_| ()),
            ),
            (
                "layer",
                exact_at(&img, &img, "edges".into(), edges.clone(), v.clone(), 1, 1).map(|_| ()),
            ),
            (
                "size",
                op_halo("forstner".into(), args(&[("size", v.clone())])).map(|_| ()),
            ),
        ] {
            let Err(e) = r else {
                // a number is a size; a string names no operator
                assert!(
                    kind == "a number" && name == "size",
                    "{name}({kind}) was taken"
                );
                continue;
            };
            let m = message(e);
            assert!(m.starts_with(&format!("{name}: ")), "{name}({kind}): {m}");
            assert!(m.len() <= 600, "{name}({kind}): {} characters", m.len());
        }
    }
}

// ---------------------------------------------------------------- the bench's fast exports

/// JS values of every kind (as tests/e2e/api-types.test.mjs passes them to the page's exports).
fn every_kind() -> Vec<(&'static str, JsValue)> {
    vec![
        ("a number", JsValue::from_f64(5.0)),
        ("NaN", JsValue::from_f64(f64::NAN)),
        ("an object", js_sys::Object::new().into()),
        (
            "an array",
            Array::of3(&1.into(), &2.into(), &3.into()).into(),
        ),
        ("null", JsValue::NULL),
        ("undefined", JsValue::UNDEFINED),
        ("a boolean", JsValue::TRUE),
        (
            "a function",
            js_sys::Function::new_no_args("return 1").into(),
        ),
        ("a typed array", Float64Array::new_with_length(3).into()),
        (
            "a Uint8Array",
            js_sys::Uint8Array::new_with_length(3).into(),
        ),
        (
            "a very long string",
            JsValue::from_str(&"x".repeat(1 << 20)),
        ),
        ("an empty string", JsValue::from_str("")),
        ("a BigInt", js_sys::BigInt::from(10).into()),
        ("a symbol", js_sys::Symbol::for_("s").into()),
        ("a Map", js_sys::Map::new().into()),
    ]
}

// The fast 8-bit exports (FastImage: the `bench` feature, in the bench's and
// the tests' builds, never in the page's): a string argument of any other
// kind or content is an Error naming it, never a trap, and the image still
// filters after them.
#[wasm_bindgen_test]
fn the_fast_exports_name_every_wrong_string_argument() {
    let bytes: Vec<u8> = (0..64).map(|i| ((i * 37) % 256) as u8).collect();
    let mut fast = FastImage::new(8, 8, &bytes).unwrap();
    fast.mean3("replicate".into()).unwrap();
    let before = fast.out_f32(0).to_vec();
    let identity = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let mut calls = 0;
    for (kind, v) in every_kind() {
        let results = [
            ("mean3", "border", fast.mean3(v.clone())),
            ("gaussian", "border", fast.gaussian(1.0, 2, v.clone())),
            ("sobel", "border", fast.sobel(v.clone())),
            ("median3", "border", fast.median3(v.clone())),
            (
                "warp_affine",
                "method",
                fast.warp_affine(&identity, v.clone(), -0.5),
            ),
        ];
        for (name, param, r) in results {
            calls += 1;
            let m = message(
                r.err()
                    .unwrap_or_else(|| panic!("{name}({kind}) was taken")),
            );
            assert!(m.starts_with(&format!("{param}: ")), "{name}({kind}): {m}");
            assert!(m.len() <= 600, "{name}({kind}): {} characters", m.len());
        }
    }
    assert_eq!(calls, 15 * 5);
    fast.mean3("replicate".into()).unwrap();
    assert_eq!(fast.out_f32(0).to_vec(), before);
    // the mean at (1, 1), row-major over the 8×8 image: its 3×3 neighbourhood's
    let mean11 = (0..3)
        .flat_map(|r| (0..3).map(move |c| r * 8 + c))
        .map(|i| f64::from(bytes[i]))
        .sum::<f64>()
        / 9.0;
    assert_eq!(before.len(), 64);
    assert!(
        (f64::from(before[9]) - mean11).abs() < 1e-4,
        "{}",
        before[9]
    );
}

#[wasm_bindgen_test]
fn photos_upright_and_probed_across_the_boundary() {
    // EXIF orientation 6: the 24 × 16 photo is upright 16 × 24
    let six = include_bytes!("corpus/orient_6.jpg");
    let img = decode_image("orient_6.jpg".into(), six).unwrap();
    assert_eq!(
        (img.width(), img.height(), img.orientation(), img.factor()),
        (16, 24, 6, 1)
    );
    // the stored top-left block (20) is at the top right
    assert_eq!(
        (img.value(15, 0), img.value(0, 0)),
        (Some(20.0), Some(140.0))
    );
    let p = img.photo().unwrap();
    assert_eq!(
        get(&p, "turned").as_string().as_deref(),
        Some("turned 90° clockwise by its EXIF orientation (6)")
    );
    assert!(get(&p, "reduced").is_undefined());
    // the header alone: the same, without decoding
    let p = probe_image("orient_6.jpg".into(), six).unwrap();
    assert_eq!(get(&p, "format").as_string().as_deref(), Some("JPEG"));
    let size =
        ["photoWidth", "photoHeight", "width", "height", "factor"].map(|k| get(&p, k).as_f64());
    assert_eq!(size, [16.0, 24.0, 16.0, 24.0, 1.0].map(Some));
    // refused by its signature, by both
    let heic = include_bytes!("corpus/iphone.heic");
    for m in [
        message(probe_image("iphone.heic".into(), heic).err().unwrap()),
        message(decode_image("iphone.heic".into(), heic).err().unwrap()),
    ] {
        assert!(m.starts_with("iphone.heic: is a HEIC/HEIF photo"), "{m}");
    }
    // a name of the wrong type is an error, not a trap
    assert!(probe_image(JsValue::from_f64(1.0), six).is_err());
}

/// A colour photo's band sent as its levels: `image_levels` gives the
/// photo's `n` and scale once, `image_from_levels` of them runs the filters
/// as the photo made from its greys (bit for bit), and levels that are not
/// whole numbers or not `width × height` are refused, naming the field.
#[wasm_bindgen_test]
fn a_colour_band_as_levels_across_the_boundary() {
    let greys: Vec<f64> = (0..35)
        .map(|i| {
            let (r, g, b) = (
                (i * 37 % 256) as f64,
                (i * 91 % 256) as f64,
                (i * 13 % 256) as f64,
            );
            photogrammetry_lab::decode::luma(r, g, b)
        })
        .collect();
    let img = image_from_grey(7, 5, &greys, 8, 255.0).unwrap();
    let lv = image_levels(&img).unwrap();
    let scale = get(&lv, "scale").as_f64().unwrap();
    assert_eq!(scale, 1000.0);
    let levels = Float32Array::from(get(&lv, "levels")).to_vec();
    assert_eq!(levels.len(), 35);
    for (n, g) in levels.iter().zip(&greys) {
        assert_eq!((f64::from(*n) / scale).to_bits(), g.to_bits());
    }
    let band = image_from_levels(7, 5, &levels, scale, 8, 255.0).unwrap();
    for kernel in ["mean", "median"] {
        let a = run_filter(
            &band,
            kernel.into(),
            "reflect".into(),
            JsValue::UNDEFINED,
            None,
        )
        .unwrap();
        let b = run_filter(
            &img,
            kernel.into(),
            "reflect".into(),
            JsValue::UNDEFINED,
            None,
        )
        .unwrap();
        assert_eq!(data(&layer(&a, 0)), data(&layer(&b, 0)));
    }
    // an 8-bit photo has no levels to send (its bytes are)
    let eight = image_from_u8(2, 1, &[3, 4]).unwrap();
    assert!(image_levels(&eight).unwrap().is_undefined());
    let e = message(
        image_from_levels(2, 1, &[1.0, 0.5], 1000.0, 8, 255.0)
            .err()
            .unwrap(),
    );
    assert!(
        e.contains("levels") && e.contains("value 2 is not a whole number"),
        "{e}"
    );
    let e = message(
        image_from_levels(3, 1, &[1.0, 2.0], 1000.0, 8, 255.0)
            .err()
            .unwrap(),
    );
    assert!(e.contains("levels"), "{e}");
    let e = message(
        image_from_levels(2, 1, &[1.0, 2.0], f64::NAN, 8, 255.0)
            .err()
            .unwrap(),
    );
    assert!(e.contains("scale"), "{e}");
}
