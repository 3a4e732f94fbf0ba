//! The page's wasm modules (`examples::MODULES`, one `web/<name>/` crate
//! each): every entry in exactly one module, each module's crate exporting
//! exactly its entries, and the catalog naming them.

use photogrammetry_playground::examples::{self, MODULES};
use std::collections::BTreeSet;
use std::path::Path;

#[test]
fn every_entry_is_in_exactly_one_module() {
    let mut seen = BTreeSet::new();
    for (name, entries) in MODULES {
        for e in entries() {
            assert!(seen.insert(e.id), "{} is in two modules", e.id);
            assert_eq!(examples::module_of(e.id), Some(name), "{}", e.id);
        }
    }
    let all: BTreeSet<_> = examples::entries().iter().map(|e| e.id).collect();
    assert_eq!(seen, all);
    assert_eq!(all.len(), 26);
    assert_eq!(examples::module_of("no-such-example"), None);
}

#[test]
fn a_module_is_one_topic_in_page_order() {
    let topics: Vec<&str> = MODULES
        .iter()
        .map(|(name, entries)| {
            let es = entries();
            let topic = es[0].topic;
            assert!(es.iter().all(|e| e.topic == topic), "{name} mixes topics");
            topic
        })
        .collect();
    assert_eq!(topics, examples::TOPICS);
}

#[test]
fn the_catalog_names_each_entrys_module() {
    let catalog = examples::catalog();
    assert_eq!(catalog.len(), examples::entries().len());
    for e in &catalog {
        let module = e.module.expect("every entry has a module");
        let (_, entries) = MODULES.iter().find(|(n, _)| *n == module).unwrap();
        assert!(entries().iter().any(|x| x.id == e.id), "{}", e.id);
        assert!(e.practice.is_some(), "{}", e.id);
    }
    // a topic module's own catalog leaves practice and module out
    let (_, coordinates) = MODULES[0];
    let own = examples::catalog_of(coordinates());
    assert_eq!(
        own.iter().map(|e| e.id).collect::<Vec<_>>(),
        ["pixel-to-photo", "gsd", "photo-to-pixel"]
    );
    assert!(own
        .iter()
        .all(|e| e.practice.is_none() && e.module.is_none()));
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
    let names: BTreeSet<String> = MODULES.iter().map(|(n, _)| n.to_string()).collect();
    assert_eq!(crates, names, "one web/<name>/ crate per module");
    for name in names {
        let lib = std::fs::read_to_string(web.join(&name).join("lib.rs")).unwrap();
        let lib: String = lib.split_whitespace().collect(); // as rustfmt may wrap it
        let call =
            format!("export_examples!(photogrammetry_playground::examples::{name}::entries);");
        assert!(lib.contains(&call), "web/{name}/lib.rs: {call}");
        let toml = std::fs::read_to_string(web.join(&name).join("Cargo.toml")).unwrap();
        assert!(
            toml.contains(&format!("name = \"playground-{name}\"")),
            "web/{name}/Cargo.toml"
        );
    }
    let core =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("www/core.js")).unwrap();
    for (name, _) in MODULES {
        assert!(
            core.contains(&format!("import(\"./pkg/{name}.js\")")),
            "www/core.js loads {name}"
        );
    }
}
