//! Issue 30, item 2, for one topic: every step with a formula carries its
//! parts, and each practice box's hints come from the relation keyed with
//! the box's value: its formula, and its numbers ending in `\;?` without the
//! answer. Shared by the topic test files (`mod parts_common;`).

use photogrammetry_playground::examples::Topic;
use photogrammetry_playground::practice::{self, split_key, value_in};
use photogrammetry_playground::solution::{num, Record, Relation, Solution};

fn keyed<'a>(s: &'a Solution, key: &str) -> Option<&'a Relation> {
    s.steps
        .iter()
        .flat_map(|st| st.parts.iter())
        .find(|r| r.key.as_deref() == Some(key))
}

/// Checks `topic`'s examples with their seed inputs and `variants`
/// practice variants each; returns how many boxes had a numbers hint.
pub fn steps_are_data_and_hints_are_keyed(topic: &Topic, variants: u32) -> usize {
    let mut with_numbers = 0;
    for e in topic.examples {
        let s = e.run(&Record::new()).unwrap();
        for st in &s.steps {
            if !st.formula.is_empty() || !st.substituted.is_empty() {
                assert!(
                    !st.parts.is_empty(),
                    "{}: step \"{}\" has no parts",
                    e.id,
                    st.title
                );
            }
            // the LaTeX is the parts' (made in one place)
            let made: Vec<String> = st
                .parts
                .iter()
                .map(Relation::substituted_latex)
                .filter(|t| !t.is_empty())
                .collect();
            assert_eq!(
                st.substituted,
                made.join(r",\quad "),
                "{}: {}",
                e.id,
                st.title
            );
        }
        if e.practice.is_none() {
            continue;
        }
        for v in 0..variants {
            let code = practice::encode(v);
            let p = practice::practice(e.id, Some(&code), 0).unwrap();
            let s = e.run(&p.inputs).unwrap();
            for b in &p.boxes {
                // the box's own element's relation (sums[1,2]), else its value's (sums)
                let (base, _) = split_key(&b.key);
                let r = keyed(&s, &b.key)
                    .or_else(|| keyed(&s, base))
                    .unwrap_or_else(|| panic!("{} {code}: no relation keyed {base}", e.id));
                assert_eq!(b.hints.numbers, r.question_latex(), "{} {}", e.id, b.key);
                // the page lays a hint out from its relation when it has symbols
                assert_eq!(
                    b.hints.relation.as_ref(),
                    (!r.symbolic.is_empty()).then_some(r),
                    "{} {}",
                    e.id,
                    b.key
                );
                if !r.symbolic.is_empty() {
                    assert_eq!(b.hints.formula, r.symbolic_latex(), "{} {}", e.id, b.key);
                }
                if b.hints.numbers.is_empty() {
                    continue;
                }
                with_numbers += 1;
                assert!(b.hints.numbers.ends_with(r"\;?"), "{}", b.hints.numbers);
                let answer = num(value_in(&s, &b.key).unwrap());
                assert!(
                    answer.len() < 4 || !b.hints.numbers.contains(&answer),
                    "{} {code} {}: {answer} in {}",
                    e.id,
                    b.key,
                    b.hints.numbers
                );
            }
        }
    }
    with_numbers
}
