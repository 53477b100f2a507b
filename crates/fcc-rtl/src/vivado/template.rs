//! Templates: `@KEY@` filling and the argument loop every script shares.

use super::DEFAULT_OUT;

/// [`fill`] for the generator's other templates.
pub(crate) fn fill_public(template: &str, vars: &[(&str, String)]) -> String {
    fill(template, vars)
}

/// Replace every `@KEY@` of `template`; a key left over is a generator bug.
pub(super) fn fill(template: &str, vars: &[(&str, String)]) -> String {
    let mut s = template.to_string();
    for (k, v) in vars {
        s = s.replace(&format!("@{k}@"), v);
    }
    debug_assert!(
        !regex::Regex::new(r"@[A-Z_0-9]+@")
            .expect("valid regex")
            .is_match(&s),
        "unfilled template key in {s}"
    );
    s
}

/// The argument loop every script shares: `-out DIR` and `-help`, plus the
/// script's own flags (`extra` are `switch` arms).
pub(super) fn args_block(extra: &str) -> String {
    fill(
        r##"set out_base @DEFAULT_OUT@
set args {}
if {[info exists ::argv]} { set args $::argv }
while {[llength $args] > 0} {
    set args [lassign $args arg]
    switch -exact -- $arg {
        -out {
            if {[llength $args] == 0} { error "-out needs a directory\n$usage" }
            set args [lassign $args out_base]
        }
@EXTRA@        -h - -help { puts $usage; return }
        default { error "unknown argument '$arg'\n$usage" }
    }
}
"##,
        &[
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("EXTRA", extra.to_string()),
        ],
    )
}
