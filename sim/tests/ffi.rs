//! The generated `fcc_ffi.h` against a real C++ compiler: it compiles, and a
//! struct whose C layout differs from the Rust one stops the build.

use std::io::Write;
use std::process::{Command, Stdio};

/// Compile `text` as C++17 (syntax only); the compiler's messages on failure.
fn compile(text: &str) -> Result<(), String> {
    let cxx = std::env::var("CXX").unwrap_or_else(|_| "c++".to_string());
    let mut child = Command::new(&cxx)
        .args(["-std=c++17", "-fsyntax-only", "-x", "c++", "-"])
        .stdin(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| {
            panic!("cannot run {cxx}: {e}; install a C++ compiler (Debian: apt-get install g++)")
        });
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(text.as_bytes())
        .expect("write to the compiler");
    let out = child.wait_with_output().expect("wait for the compiler");
    if out.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&out.stderr).into_owned())
    }
}

#[test]
fn generated_header_compiles_and_its_layout_asserts_hold() {
    let h = fcc_sim::ffi::header();
    if let Err(log) = compile(&h) {
        panic!("fcc_ffi.h does not compile:\n{log}\n{h}");
    }
}

#[test]
fn field_whose_c_offset_differs_from_rust_fails_the_build() {
    // A C field widened behind the Rust struct's back shifts every later field.
    let h = fcc_sim::ffi::header().replacen(
        "    uint8_t s_axis_tvalid;",
        "    uint16_t s_axis_tvalid;",
        1,
    );
    assert!(
        h.contains("uint16_t s_axis_tvalid;"),
        "FccIn.s_axis_tvalid not found in the header"
    );
    let log = compile(&h).expect_err("a drifted layout must not compile");
    assert!(
        log.contains("FccIn.s_axis_tlast: offset differs"),
        "unexpected message:\n{log}"
    );
}
