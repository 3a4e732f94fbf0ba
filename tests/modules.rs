//! The page's wasm modules (one per topic of `examples::TOPICS`, one
//! `web/<module>/` crate each): every example in exactly one module, each
//! module's crate exporting exactly its topic, and the catalog derived from
//! the descriptors.

use photogrammetry_playground::examples::{self, TOPICS};
use std::collections::BTreeSet;
use std::path::Path;

#[test]
fn every_example_is_in_exactly_one_topic_and_module() {
    let mut seen = BTreeSet::new();
    let mut modules = BTreeSet::new();
    for t in &TOPICS {
        assert!(
            modules.insert(t.module),
            "two topics use module {}",
            t.module
        );
        assert!(!t.examples.is_empty(), "{} has no examples", t.title);
        for e in t.examples {
            assert!(seen.insert(e.id), "{} is in two topics", e.id);
            assert_eq!(examples::module_of(e.id), Some(t.module), "{}", e.id);
        }
    }
    let all: BTreeSet<_> = examples::all().map(|e| e.id).collect();
    assert_eq!(seen, all);
    assert_eq!(examples::module_of("no-such-example"), None);
}

#[test]
fn the_catalog_is_the_descriptors_in_page_order() {
    let catalog = examples::catalog();
    let ids: Vec<_> = catalog.iter().map(|e| e.id).collect();
    let described: Vec<_> = examples::all().map(|e| e.id).collect();
    assert_eq!(ids, described);
    for e in &catalog {
        let t = TOPICS.iter().find(|t| t.module == e.module).unwrap();
        assert_eq!(e.topic, t.title, "{}", e.id);
        assert!(t.examples.iter().any(|x| x.id == e.id), "{}", e.id);
        assert!(e.practice, "{} has practice", e.id);
    }
    // topics in page order, each example's entries together
    let topics: Vec<&str> = catalog.iter().map(|e| e.topic).collect();
    let mut order: Vec<&str> = topics.clone();
    order.dedup();
    assert_eq!(order, TOPICS.iter().map(|t| t.title).collect::<Vec<_>>());
    // a topic module's own catalog: its examples only
    let own = examples::catalog_of(&TOPICS[..1]);
    assert_eq!(
        own.iter().map(|e| e.id).collect::<Vec<_>>(),
        TOPICS[0].examples.iter().map(|e| e.id).collect::<Vec<_>>()
    );
}

#[test]
fn each_module_has_its_crate_exporting_its_entries() {
    let web = Path::new(env!("CARGO_MANIFEST_DIR")).join("web");
    let mut crates: BTreeSet<String> = std::fs::read_dir(&web)
        .unwrap()
        .map(|d| d.unwrap().file_name().into_string().unwrap())
        .collect();
    assert!(
        crates.remove("all"),
        "web/all/ (practice and the one-package API)"
    );
    let all = std::fs::read_to_string(web.join("all/lib.rs")).unwrap();
    assert!(all.contains("export_all!()"));
    let names: BTreeSet<String> = TOPICS.iter().map(|t| t.module.to_string()).collect();
    assert_eq!(crates, names, "one web/<name>/ crate per module");
    for name in names {
        let lib = std::fs::read_to_string(web.join(&name).join("lib.rs")).unwrap();
        let lib: String = lib.split_whitespace().collect(); // as rustfmt may wrap it
        let call = format!("export_examples!(photogrammetry_playground::examples::{name}::TOPIC);");
        assert!(lib.contains(&call), "web/{name}/lib.rs: {call}");
        let toml = std::fs::read_to_string(web.join(&name).join("Cargo.toml")).unwrap();
        assert!(
            toml.contains(&format!("name = \"playground-{name}\"")),
            "web/{name}/Cargo.toml"
        );
    }
    let core =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("www/core.js")).unwrap();
    for name in TOPICS.iter().map(|t| t.module) {
        assert!(
            core.contains(&format!("import(\"./pkg/{name}.js\")")),
            "www/core.js loads {name}"
        );
        assert!(
            core.contains(&format!("import(\"./pkg/{name}_practice.js\")")),
            "www/core.js loads {name}'s practice module"
        );
    }
}
