//! The README's pictures: each is committed, and each excerpt shown under it is code the
//! examples really run (so the README cannot drift from what draws the pictures).

use std::{fs, path::Path};

/// The lines of `text`, each trimmed, blank ones dropped.
fn normalized(text: &str) -> Vec<String> {
    text.lines()
        .map(|l| l.trim().to_string())
        .filter(|l| !l.is_empty())
        .collect()
}

#[test]
fn pictures_exist_and_their_excerpts_are_the_examples_code() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = fs::read_to_string(root.join("README.md")).unwrap();
    let section = readme
        .split("\n## Pictures\n")
        .nth(1)
        .expect("README has a Pictures section");
    let section = section.split("\n## ").next().unwrap();
    let sources: Vec<Vec<String>> = [
        "examples/showcase.rs",
        "examples/common/breakout.rs",
        "examples/common/cube.rs",
    ]
    .iter()
    .map(|f| normalized(&fs::read_to_string(root.join(f)).unwrap()))
    .collect();

    let mut pictures = 0;
    for line in section.lines().filter(|l| l.starts_with("![")) {
        let path = line.split("](").nth(1).unwrap().trim_end_matches(')');
        let bytes = fs::read(root.join(path)).unwrap_or_else(|_| panic!("{path} is committed"));
        assert!(bytes.starts_with(b"\x89PNG"), "{path} is a PNG");
        assert!(bytes.len() < 64 * 1024, "{path} is small");
        pictures += 1;
    }
    let mut excerpts = 0;
    for block in section.split("```rust,ignore\n").skip(1) {
        let code = normalized(block.split("```").next().unwrap());
        let found = sources
            .iter()
            .any(|source| source.windows(code.len()).any(|w| w == code.as_slice()));
        assert!(
            found,
            "README excerpt not found in the examples:\n{}",
            code.join("\n")
        );
        excerpts += 1;
    }
    assert!(pictures >= 8, "{pictures} pictures");
    assert_eq!(excerpts, pictures, "one excerpt per picture");
}
