//! Label files and label bookkeeping: SemanticKITTI `.label`, the
//! `--min-points` filter, and ground-truth instances from SemanticKITTI
//! labels.
//!
//! A SemanticKITTI `.label` file holds one little-endian `u32` per point of
//! its scan: the semantic class in the lower 16 bits, the instance id in the
//! upper 16.

use crate::error::{LidarError, Result};
use std::collections::HashMap;
use std::path::Path;

/// Semantic class written for points ground removal took
/// (SemanticKITTI "other-ground"; clusters themselves carry class 0, since
/// FCC does not classify).
pub const SEMANTIC_GROUND: u16 = 49;

/// SemanticKITTI classes that have instances ("things"), moving variants included.
pub const THING_CLASSES: [u16; 18] = [
    10, 11, 13, 15, 16, 18, 20, 30, 31, 32, 252, 253, 254, 255, 256, 257, 258, 259,
];

/// Pack a semantic class and an instance id.
pub fn pack_label(semantic: u16, instance: u16) -> u32 {
    (u32::from(instance) << 16) | u32::from(semantic)
}

/// Split a packed label into (semantic, instance).
pub fn unpack_label(label: u32) -> (u16, u16) {
    ((label & 0xffff) as u16, (label >> 16) as u16)
}

/// The default semantic class of clustered points in `.label` files:
/// SemanticKITTI "car" (10), the commonest thing class, so the dataset's
/// own evaluator takes fcc's clusters as instances.
pub const DEFAULT_LABEL_CLASS: u16 = 10;

/// Raw SemanticKITTI labels: per point, the cluster id as instance with
/// class `class` (0 = none, class 0), and class [`SEMANTIC_GROUND`] where
/// `ground` says so.
pub fn semantic_labels(instances: &[u32], ground: Option<&[bool]>, class: u16) -> Result<Vec<u32>> {
    if let Some(g) = ground {
        if g.len() != instances.len() {
            return Err(LidarError::Mismatch {
                what: "ground flags for the labels".into(),
                expected: instances.len(),
                got: g.len(),
            });
        }
    }
    instances
        .iter()
        .enumerate()
        .map(|(i, &inst)| {
            let inst16 = u16::try_from(inst).map_err(|_| {
                LidarError::Config(format!(
                    "cluster id {inst} does not fit the 16-bit instance field of a .label file"
                ))
            })?;
            Ok(if inst16 != 0 {
                pack_label(class, inst16)
            } else if ground.is_some_and(|g| g[i]) {
                pack_label(SEMANTIC_GROUND, 0)
            } else {
                0
            })
        })
        .collect()
}

/// Write a SemanticKITTI `.label` file: per point, the cluster id as
/// instance (0 = none) with class `class`, and class [`SEMANTIC_GROUND`]
/// where `ground` says so.
pub fn write_label_file(
    path: &Path,
    instances: &[u32],
    ground: Option<&[bool]>,
    class: u16,
) -> Result<()> {
    let labels = semantic_labels(instances, ground, class).map_err(|e| match e {
        LidarError::Config(m) => LidarError::Config(format!("{}: {m}", path.display())),
        LidarError::Mismatch {
            what,
            expected,
            got,
        } => LidarError::Mismatch {
            what: format!("{what} of {}", path.display()),
            expected,
            got,
        },
        e => e,
    })?;
    let mut out = Vec::with_capacity(labels.len() * 4);
    for l in labels {
        out.extend_from_slice(&l.to_le_bytes());
    }
    fcc_io::write_atomic(path, &out).map_err(|e| LidarError::io(path, e))
}

/// Read a `.label` file; with `points`, its length must match the scan.
pub fn read_label_file(path: &Path, points: Option<usize>) -> Result<Vec<u32>> {
    let bytes = std::fs::read(path).map_err(|e| LidarError::io(path, e))?;
    if bytes.len() % 4 != 0 {
        return Err(LidarError::not_format(
            path,
            "SemanticKITTI .label",
            format!(
                "{} bytes is not a whole number of 4-byte labels",
                bytes.len()
            ),
        ));
    }
    let labels: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    if let Some(n) = points {
        if labels.len() != n {
            return Err(LidarError::malformed(
                path,
                format!("{} labels for a scan of {n} points", labels.len()),
            ));
        }
    }
    Ok(labels)
}

/// Ground-truth instances from SemanticKITTI labels: every (class, instance)
/// pair of a thing class with a non-zero instance id becomes one instance,
/// numbered from 1 in order of first appearance; everything else is 0.
pub fn semantickitti_instances(labels: &[u32]) -> Vec<u32> {
    let mut ids: HashMap<u32, u32> = HashMap::new();
    labels
        .iter()
        .map(|&l| {
            let (sem, inst) = unpack_label(l);
            if inst == 0 || !THING_CLASSES.contains(&sem) {
                return 0;
            }
            let next = ids.len() as u32 + 1;
            *ids.entry(l).or_insert(next)
        })
        .collect()
}

/// Drop clusters of `min_points` points or fewer (their pixels become 0)
/// and renumber the rest 1..=n in order of first appearance, which keeps
/// the golden model's raster numbering. Returns the labels and n.
pub fn filter_min_points(labels: &[u32], min_points: usize) -> (Vec<u32>, u32) {
    let mut size: HashMap<u32, usize> = HashMap::new();
    for &l in labels.iter().filter(|&&l| l != 0) {
        *size.entry(l).or_insert(0) += 1;
    }
    let mut map: HashMap<u32, u32> = HashMap::new();
    let out = labels
        .iter()
        .map(|&l| {
            if l == 0 || size[&l] <= min_points {
                return 0;
            }
            let next = map.len() as u32 + 1;
            *map.entry(l).or_insert(next)
        })
        .collect();
    (out, map.len() as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn min_points_drops_small_clusters_and_renumbers() {
        let labels = [0, 1, 1, 2, 3, 3, 3, 2, 4];
        assert_eq!(filter_min_points(&labels, 0), (labels.to_vec(), 4));
        assert_eq!(
            filter_min_points(&labels, 1),
            (vec![0, 1, 1, 2, 3, 3, 3, 2, 0], 3)
        );
        assert_eq!(
            filter_min_points(&labels, 2),
            (vec![0, 0, 0, 0, 1, 1, 1, 0, 0], 1)
        );
        assert_eq!(filter_min_points(&labels, 3).1, 0);
    }

    #[test]
    fn label_files_round_trip_and_check_sizes() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("000000.label");
        write_label_file(&p, &[0, 5, 70_000 - 4_465], Some(&[true, false, false]), 0).unwrap();
        let raw = read_label_file(&p, Some(3)).unwrap();
        assert_eq!(
            raw.iter().map(|&l| unpack_label(l)).collect::<Vec<_>>(),
            vec![(49, 0), (0, 5), (0, 65_535)]
        );
        write_label_file(
            &p,
            &[0, 5, 0],
            Some(&[true, false, false]),
            DEFAULT_LABEL_CLASS,
        )
        .unwrap();
        let raw = read_label_file(&p, Some(3)).unwrap();
        assert_eq!(
            raw.iter().map(|&l| unpack_label(l)).collect::<Vec<_>>(),
            vec![(49, 0), (10, 5), (0, 0)]
        );
        let err = read_label_file(&p, Some(4)).unwrap_err().to_string();
        assert!(
            err.contains("000000.label") && err.contains("3 labels for a scan of 4 points"),
            "{err}"
        );
        let err = write_label_file(&p, &[70_000], None, 0)
            .unwrap_err()
            .to_string();
        assert!(err.contains("cluster id 70000 does not fit"), "{err}");
        std::fs::write(&p, [1u8, 2, 3]).unwrap();
        assert!(read_label_file(&p, None)
            .unwrap_err()
            .to_string()
            .contains("not a whole number of 4-byte labels"));
    }

    #[test]
    fn instances_from_semantickitti_things_only() {
        let car_a = pack_label(10, 3);
        let car_b = pack_label(10, 4);
        let person = pack_label(30, 3);
        let moving_car = pack_label(252, 3);
        let road = pack_label(40, 0);
        let building_with_id = pack_label(50, 7);
        let labels = [
            road,
            car_a,
            person,
            car_a,
            car_b,
            building_with_id,
            moving_car,
            pack_label(10, 0),
        ];
        assert_eq!(
            semantickitti_instances(&labels),
            vec![0, 1, 2, 1, 3, 0, 4, 0]
        );
    }
}
