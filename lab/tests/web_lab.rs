//! The lab's wasm boundary in headless Chromium: decoding (good and bad
//! files) and one operator of each family, as the worker calls them.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Float64Array, Reflect};
use photogrammetry_lab::wasm::*;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn layer(v: &JsValue, i: u32) -> JsValue {
    Array::from(v).get(i)
}

fn data(l: &JsValue) -> Vec<f64> {
    Float64Array::from(get(l, "data")).to_vec()
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
    let img = decode_image("grey8.png", GREY8).unwrap();
    assert_eq!((img.width(), img.height(), img.bits()), (4, 3, 8));
    assert_eq!(
        img.grey().to_vec(),
        (0..12)
            .map(|i| (10 * (i % 4) + 40 * (i / 4)) as f64)
            .collect::<Vec<_>>()
    );
    let img = decode_image("grey16.png", GREY16).unwrap();
    assert_eq!(img.value(3, 2), Some(43007.0));
    assert_eq!(img.max_value(), 65535.0);
    let img = decode_image("grey16_strips.tif", TIFF16).unwrap();
    assert_eq!(
        (img.format(), img.value(3, 2)),
        ("TIFF".to_string(), Some(43007.0))
    );
    let img = decode_image("blocks.jpg", JPEG).unwrap();
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
    ] {
        let m = message(decode_image(name, bytes).err().expect(name));
        assert!(
            m.starts_with(&format!("{name}: ")) && m.contains(says),
            "{m}"
        );
    }
    // and the module keeps working
    assert!(decode_image("grey8.png", GREY8).is_ok());
}

#[wasm_bindgen_test]
fn one_operator_of_each_family_across_the_boundary() {
    let img = decode_image("grey8.png", GREY8).unwrap();
    // filter: the 3×3 mean at (1, 1) of g = 10c + 40r is g(1, 1) = 50
    let out = run_filter(&img, "mean", "crop", None, None).unwrap();
    let l = layer(&out, 0);
    assert_eq!(get(&l, "c0").as_f64(), Some(1.0));
    assert!((data(&l)[0] - 50.0).abs() < 1e-12);
    // edges: Sobel gx (top minus bottom, weights 1 2 1) of a ramp rising 40 a
    // row is 4·(−80) = −320; gy (right minus left) 4·20 = 80
    let out = run_edges(&img, "sobel", "crop").unwrap();
    assert!((data(&layer(&out, 0))[0] + 320.0).abs() < 1e-12);
    assert!((data(&layer(&out, 1))[0] - 80.0).abs() < 1e-12);
    // interest: the frame sample's maps exist where a 5×5 window fits
    let frame = scanned_frame();
    let out = run_moravec(&frame, 4, 1e9).unwrap();
    assert_eq!(Float64Array::from(get(&out, "points")).length(), 0);
    // correlation: a template found in its own image with ρ = 1
    let t = [40.0, 490.0, 21.0, 21.0];
    let s = [30.0, 480.0, 41.0, 41.0];
    let out = run_correlation(&frame, &t, &frame, &s, "shift").unwrap();
    let best = Float64Array::from(get(&out, "best")).to_vec();
    assert_eq!(best, vec![50.0, 500.0]);
    // resampling: scale 1, angle 0 reproduces the image by all three methods
    let out = run_resample(&img, "rotate", &[0.0, 1.0], 4, 3).unwrap();
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
    let m = message(run_filter(&img, "blur", "crop", None, None).err().unwrap());
    assert!(m.starts_with("kernel: "), "{m}");
    let m = message(
        run_correlation(&frame, &[0.0, 0.0, 4.0, 4.0], &frame, &s, "shift")
            .err()
            .unwrap(),
    );
    assert!(m.starts_with("template: "), "{m}");
}

#[wasm_bindgen_test]
fn a_custom_kernel_and_a_kept_forstner_map_across_the_boundary() {
    let img = decode_image("grey8.png", GREY8).unwrap();
    // [1 2 1] normalised (÷4) along a row of g = 10c + 40r: g itself inside
    let out = run_filter(&img, "custom", "crop", Some("1, 2, 1".into()), None).unwrap();
    let l = layer(&out, 0);
    assert_eq!(get(&l, "name").as_string().unwrap(), "custom");
    assert_eq!(data(&l)[0], 10.0);
    // the same kernel with divisor 1: four times that
    let out = run_filter(&img, "custom", "crop", Some("1 2 1".into()), Some(1.0)).unwrap();
    assert_eq!(data(&layer(&out, 0))[0], 40.0);
    let checked = check_custom_kernel("1 2 1\n2 4 2\n1 2 1", None).unwrap();
    assert_eq!(get(&checked, "divisor").as_f64(), Some(16.0));
    for (text, d, says) in [
        ("1 2 x", None, "custom_kernel: row 1: \"x\" is not a number"),
        ("1 2 1; 1 2", None, "custom_kernel: row 2 has 2 numbers"),
        ("1 1", None, "custom_kernel: is 1×2"),
        ("-1 0 1", None, "custom_divisor: the weights sum to 0"),
        ("1 2 1", Some(0.0), "custom_divisor: must be"),
    ] {
        let m = message(
            run_filter(&img, "custom", "crop", Some(text.into()), d)
                .err()
                .unwrap(),
        );
        assert!(m.starts_with(says), "{m}");
    }
    let m = message(
        run_filter(&img, "custom", "crop", None, None)
            .err()
            .unwrap(),
    );
    assert!(m.starts_with("custom_kernel: is missing"), "{m}");
    // Förstner: the kept map's points for a threshold equal a full run's
    // (a 64 × 48 checkerboard of 8-pixel squares with a texture)
    let bytes: Vec<u8> = (0..64 * 48)
        .map(|i| {
            let (c, r) = (i % 64, i / 64);
            (if ((c / 8) + (r / 8)) % 2 == 1 {
                200
            } else {
                50
            } + (c * 7 + r * 13) % 17) as u8
        })
        .collect();
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
