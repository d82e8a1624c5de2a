//! A sweep spec whose grids multiply to more cases than a spec may define ([`rollbem::sweep::MAX_CASES`], 10^8) is
//! refused when it is read, naming `grid` (fuzz target `sweep_spec`; inputs in `fuzz/regressions/`). Before, such a
//! spec was accepted: 2^40 cases then aborted the process when `cases` reserved room for them, and 2^64 overflowed
//! the count (a panic with overflow checks, a wrong count of 0 without: `len()` wrapped). (Below that, a sweep of
//! more than [`rollbem::sweep::LARGE_SWEEP_CASES`] cases reads but needs `--allow-large` to run:
//! `tests/sweep_resume.rs`.)

use rollbem::sweep::{SweepSpec, MAX_CASES};
use rollbem::Error;
use std::path::Path;

fn refused(name: &str) -> (String, String) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions").join(name);
    match SweepSpec::from_file(&path) {
        Err(Error::Invalid { field, message, .. }) => (field, message),
        Err(e) => panic!("{name}: expected an invalid-field error, got {e}"),
        Ok(spec) => panic!("{name}: accepted, with len() = {}", spec.len()),
    }
}

#[test]
fn two_to_the_40_cases_are_refused_naming_the_grid() {
    let (field, message) = refused("sweep-2pow40-cases.toml");
    assert_eq!(field, "grid");
    // 2^40, counted exactly (it fits in a usize).
    assert!(
        message.contains(&format!("{} cases", 1u64 << 40)) && message.contains(&MAX_CASES.to_string()),
        "{message}"
    );
}

#[test]
fn a_count_beyond_usize_is_refused_not_wrapped() {
    let (field, message) = refused("sweep-2pow64-cases.toml");
    assert_eq!(field, "grid");
    assert!(message.contains(&format!("more than {}", usize::MAX)), "{message}");
}

#[test]
fn the_limit_itself_is_allowed() {
    // MAX_CASES = 10^8: eight keys of ten values each is exactly the limit; one more value is over it.
    let keys = |last: usize| -> String {
        let ten: Vec<String> = (1..=10).map(|v| v.to_string()).collect();
        let mut s = String::from("name = \"limit\"\nbase = \"b.toml\"\n[[grid]]\n");
        for k in 0..7 {
            s += &format!("\"checks.k{k}\" = [{}]\n", ten.join(", "));
        }
        let values: Vec<String> = (1..=last).map(|v| v.to_string()).collect();
        s + &format!("\"checks.k7\" = [{}]\n", values.join(", "))
    };
    assert_eq!(MAX_CASES, 100_000_000);
    let spec = SweepSpec::from_toml(&keys(10), Path::new("limit.toml")).expect("exactly the limit");
    assert_eq!(spec.len(), MAX_CASES);
    assert!(SweepSpec::from_toml(&keys(11), Path::new("limit.toml")).is_err());
}

#[test]
fn a_value_with_a_line_break_is_refused() {
    // A sweep CSV has one line per row (its journal finds a cut row by the last line break).
    let text = "name = \"x\"\nbase = \"b.toml\"\n[[grid]]\n\"description\" = [\"one\", \"two\\nlines\"]\n";
    match SweepSpec::from_toml(text, Path::new("x.toml")) {
        Err(Error::Invalid { field, message, .. }) => {
            assert_eq!(field, "grid.description");
            assert!(message.contains("line break"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}
