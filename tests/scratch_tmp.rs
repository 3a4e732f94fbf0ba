use photogrammetry_playground::examples;
use photogrammetry_playground::practice::{inputs_of, specs};
#[test]
fn dump() {
    for s in specs() {
        if ![
            "gsd",
            "fiducial-similarity",
            "fiducial-affine",
            "transform-fit",
            "lsm-1d",
            "lsm-2d",
            "lsm-affine",
            "resample",
            "filter-window",
            "edge-window",
            "moravec-window",
            "chain-code",
            "boundary-length",
            "boundary-shape",
        ]
        .contains(&s.id)
        {
            continue;
        }
        let i = inputs_of(&s, 7);
        let sol = examples::solve(s.id, &i).unwrap();
        println!(
            "=== {} inputs: {}",
            s.id,
            format!("{:?}", i).chars().take(400).collect::<String>()
        );
        let r = format!("{:?}", sol.result);
        println!("result: {}", r.chars().take(900).collect::<String>());
        let keys: Vec<String> = sol
            .steps
            .iter()
            .flat_map(|st| {
                st.values
                    .iter()
                    .map(|(k, _)| k.to_string())
                    .collect::<Vec<_>>()
            })
            .collect();
        println!("step keys: {:?}", keys);
    }
}
