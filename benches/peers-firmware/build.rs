//! Puts the repository's `memory.x` (QEMU's MPS2 memory map) where cortex-m-rt's `link.x` finds it.
fn main() {
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::copy("../../memory.x", out.join("memory.x")).expect("memory.x at the top level");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=../../memory.x");
}
