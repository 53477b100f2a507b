//! Comparison with the golden model, with first-mismatch diagnostics.

use fcc_golden::{cluster, Clustering, Frame, MergeMode};
use fcc_params::FccParams;

use crate::drive::FrameRun;
use crate::SimError;

/// The golden model's exact clustering of `frame`.
pub fn expected(p: &FccParams, frame: &Frame) -> Result<Clustering, SimError> {
    Ok(cluster(p, frame, MergeMode::Exact)?)
}

/// Compare a run with the golden result bit for bit. `what` names the case
/// (frame name and seed) in the error.
pub fn compare(
    p: &FccParams,
    gold: &Clustering,
    run: &FrameRun,
    what: &str,
) -> Result<(), SimError> {
    let tag = format!("fsize {} {}x{} {what}", p.fsize, p.rows, p.cols);
    if let Some(i) = (0..gold.labels.len()).find(|&i| run.labels.get(i) != Some(&gold.labels[i])) {
        let bad = gold
            .labels
            .iter()
            .zip(&run.labels)
            .filter(|(a, b)| a != b)
            .count();
        return Err(SimError::Mismatch(format!(
            "{tag}: first mismatch at row {} col {}: expected {} != got {} ({bad} pixels differ)",
            i / p.cols,
            i % p.cols,
            gold.labels[i],
            run.labels
                .get(i)
                .map_or("nothing".to_string(), |v| v.to_string()),
        )));
    }
    let pairs = [
        (
            "clusters",
            u64::from(gold.clusters),
            u64::from(run.clusters),
        ),
        (
            "provisional",
            u64::from(gold.provisional),
            u64::from(run.provisional),
        ),
        (
            "overflow",
            u64::from(gold.overflow),
            u64::from(run.overflow),
        ),
        (
            "unlabelled",
            gold.unlabelled as u64,
            u64::from(run.unlabelled),
        ),
    ];
    for (name, e, g) in pairs {
        if e != g {
            return Err(SimError::Mismatch(format!(
                "{tag}: status {name}: expected {e} != got {g}"
            )));
        }
    }
    Ok(())
}
