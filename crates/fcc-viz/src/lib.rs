//! A live Foxglove WebSocket server of clustered frames, built with the
//! Foxglove SDK: per frame, on `/fcc/points`, a `foxglove.PointCloud` of the
//! frame's points coloured by cluster (fields x, y, z float32, label uint32,
//! red, green, blue, alpha uint8), and on `/fcc/clusters` a
//! `foxglove.SceneUpdate` that replaces the previous frame's boxes with one
//! entity per cluster (id `cluster-<id>`: the record's oriented box and z
//! extent, and its id as a text label). Open it in Foxglove with "Open
//! connection", `ws://HOST:PORT`.
//!
//! A crate of its own, so that the readers do not carry the SDK's
//! dependencies.

use fcc_lidar::clusters::ClusterRow;
use fcc_lidar::picture::cluster_colour;
use foxglove::messages::packed_element_field::NumericType;
use foxglove::messages::{
    Color, CubePrimitive, PackedElementField, PointCloud, Pose, Quaternion, SceneEntity,
    SceneEntityDeletion, SceneUpdate, TextPrimitive, Timestamp, Vector3,
};
use foxglove::{Channel, Context, WebSocketServerHandle};
use std::sync::Arc;

/// Topic of the point clouds.
pub const POINTS_TOPIC: &str = "/fcc/points";
/// Topic of the boxes.
pub const CLUSTERS_TOPIC: &str = "/fcc/clusters";
/// Default address of the server (Foxglove's usual port).
pub const DEFAULT_ADDR: &str = "127.0.0.1:8765";

/// Why the server could not start.
#[derive(Debug, thiserror::Error)]
#[error("foxglove server on {addr}: {reason}")]
pub struct VizError {
    pub addr: String,
    pub reason: String,
}

/// One clustered frame, as the server takes it.
#[derive(Debug, Clone, Copy)]
pub struct VizFrame<'a> {
    /// The frame's time, nanoseconds since the epoch.
    pub stamp_ns: u64,
    /// The coordinate frame of the points.
    pub frame_id: &'a str,
    pub points: &'a [[f32; 3]],
    /// Cluster of each point, 0 for none.
    pub labels: &'a [u32],
    pub clusters: &'a [ClusterRow],
}

/// A running server and its two channels.
pub struct FoxgloveServer {
    handle: Option<WebSocketServerHandle>,
    points: Channel<PointCloud>,
    scene: Channel<SceneUpdate>,
    /// Entity ids of the boxes shown, deleted by the next frame.
    shown: Vec<String>,
    _context: Arc<Context>,
}

impl FoxgloveServer {
    /// Start a server on `addr` (`HOST:PORT`; port 0: the system's choice).
    pub fn start(addr: &str) -> Result<FoxgloveServer, VizError> {
        let bad = |reason: String| VizError {
            addr: addr.to_string(),
            reason,
        };
        let (host, port) = addr
            .rsplit_once(':')
            .and_then(|(h, p)| Some((h.trim_matches(['[', ']']), p.parse::<u16>().ok()?)))
            .ok_or_else(|| bad("give HOST:PORT, e.g. 127.0.0.1:8765".into()))?;
        let context = Context::new();
        let handle = context
            .websocket_server()
            .name("fcc")
            .bind(host, port)
            .start_blocking()
            .map_err(|e| bad(e.to_string()))?;
        let points = context.channel_builder(POINTS_TOPIC).build::<PointCloud>();
        let scene = context
            .channel_builder(CLUSTERS_TOPIC)
            .build::<SceneUpdate>();
        Ok(FoxgloveServer {
            handle: Some(handle),
            points,
            scene,
            shown: Vec::new(),
            _context: context,
        })
    }

    /// The port the server listens on.
    pub fn port(&self) -> u16 {
        self.handle.as_ref().map_or(0, WebSocketServerHandle::port)
    }

    /// Clients connected now.
    pub fn clients(&self) -> usize {
        self.handle
            .as_ref()
            .map_or(0, WebSocketServerHandle::client_count)
    }

    /// Send one frame to every client: its point cloud and its boxes.
    pub fn publish(&mut self, f: &VizFrame) {
        let stamp = timestamp(f.stamp_ns);
        self.points
            .log_with_time(&point_cloud(f, stamp), f.stamp_ns);
        let deletions = self
            .shown
            .drain(..)
            .map(|id| SceneEntityDeletion {
                timestamp: Some(stamp),
                r#type: 0, // MATCHING_ID
                id,
            })
            .collect();
        let entities: Vec<SceneEntity> = f.clusters.iter().map(|r| entity(f, stamp, r)).collect();
        self.shown = entities.iter().map(|e| e.id.clone()).collect();
        self.scene.log_with_time(
            &SceneUpdate {
                deletions,
                entities,
            },
            f.stamp_ns,
        );
    }
}

impl Drop for FoxgloveServer {
    fn drop(&mut self) {
        if let Some(h) = self.handle.take() {
            drop(h.stop());
        }
    }
}

fn timestamp(ns: u64) -> Timestamp {
    let sec = u32::try_from(ns / 1_000_000_000).unwrap_or(u32::MAX);
    Timestamp::new(sec, (ns % 1_000_000_000) as u32)
}

/// x y z float32, label uint32, red green blue alpha uint8: 20 bytes a point.
fn point_cloud(f: &VizFrame, stamp: Timestamp) -> PointCloud {
    let field = |name: &str, offset: u32, t: NumericType| PackedElementField {
        name: name.into(),
        offset,
        r#type: t as i32,
    };
    let fields = vec![
        field("x", 0, NumericType::Float32),
        field("y", 4, NumericType::Float32),
        field("z", 8, NumericType::Float32),
        field("label", 12, NumericType::Uint32),
        field("red", 16, NumericType::Uint8),
        field("green", 17, NumericType::Uint8),
        field("blue", 18, NumericType::Uint8),
        field("alpha", 19, NumericType::Uint8),
    ];
    let mut data = Vec::with_capacity(20 * f.points.len());
    for (p, &l) in f.points.iter().zip(f.labels) {
        for v in p {
            data.extend_from_slice(&v.to_le_bytes());
        }
        data.extend_from_slice(&l.to_le_bytes());
        let rgb = if l == 0 { [128; 3] } else { cluster_colour(l) };
        data.extend_from_slice(&rgb);
        data.push(255);
    }
    PointCloud {
        timestamp: Some(stamp),
        frame_id: f.frame_id.into(),
        pose: None,
        point_stride: 20,
        fields,
        data: data.into(),
    }
}

/// The box and id label of one cluster.
fn entity(f: &VizFrame, stamp: Timestamp, r: &ClusterRow) -> SceneEntity {
    let [cr, cg, cb] = cluster_colour(r.cluster);
    let color = Color {
        r: f64::from(cr) / 255.0,
        g: f64::from(cg) / 255.0,
        b: f64::from(cb) / 255.0,
        a: 0.5,
    };
    let z = f64::from(r.min_z + r.max_z) / 2.0;
    let pose = |zz: f64| Pose {
        position: Some(Vector3 {
            x: r.box_cx,
            y: r.box_cy,
            z: zz,
        }),
        orientation: Some(Quaternion {
            x: 0.0,
            y: 0.0,
            z: (r.box_yaw / 2.0).sin(),
            w: (r.box_yaw / 2.0).cos(),
        }),
    };
    SceneEntity {
        timestamp: Some(stamp),
        frame_id: f.frame_id.into(),
        id: format!("cluster-{}", r.cluster),
        cubes: vec![CubePrimitive {
            pose: Some(pose(z)),
            size: Some(Vector3 {
                x: r.box_length.max(0.01),
                y: r.box_width.max(0.01),
                z: f64::from(r.max_z - r.min_z).max(0.01),
            }),
            color: Some(color),
        }],
        texts: vec![TextPrimitive {
            pose: Some(pose(f64::from(r.max_z) + 0.3)),
            billboard: true,
            font_size: 14.0,
            scale_invariant: true,
            color: Some(Color { a: 1.0, ..color }),
            text: r.cluster.to_string(),
        }],
        ..SceneEntity::default()
    }
}
