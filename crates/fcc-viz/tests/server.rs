//! The Foxglove server on the loopback: a WebSocket client connects with the
//! Foxglove subprotocol, sees both channels advertised, subscribes to each
//! and receives a message of each. Bounded: every read times out, and the
//! test gives up after a few seconds.

use fcc_lidar::clusters::ClusterRow;
use fcc_viz::{FoxgloveServer, VizFrame, CLUSTERS_TOPIC, POINTS_TOPIC};
use serde_json::Value;
use std::collections::BTreeMap;
use std::time::{Duration, Instant};
use tungstenite::client::IntoClientRequest;
use tungstenite::stream::MaybeTlsStream;
use tungstenite::Message;

#[test]
fn a_client_receives_the_points_and_the_boxes() {
    let mut server = FoxgloveServer::start("127.0.0.1:0").unwrap();
    let port = server.port();
    assert_ne!(port, 0);
    let mut req = format!("ws://127.0.0.1:{port}")
        .into_client_request()
        .unwrap();
    req.headers_mut()
        .insert("Sec-WebSocket-Protocol", "foxglove.sdk.v1".parse().unwrap());
    let (mut ws, _) = tungstenite::connect(req).unwrap();
    if let MaybeTlsStream::Plain(s) = ws.get_mut() {
        s.set_read_timeout(Some(Duration::from_millis(100)))
            .unwrap();
    }
    let rows = [ClusterRow {
        cluster: 1,
        box_cx: 5.0,
        box_length: 2.0,
        box_width: 1.0,
        max_z: 1.0,
        ..ClusterRow::default()
    }];
    let frame = VizFrame {
        stamp_ns: 1_700_000_000_000_000_000,
        frame_id: "lidar",
        points: &[[5.0, 0.0, 0.5], [9.0, 1.0, 0.0]],
        labels: &[1, 0],
        clusters: &rows,
    };
    let start = Instant::now();
    // Channel id by topic, then subscription id -> topic, then topics received.
    let mut channels: BTreeMap<String, u64> = BTreeMap::new();
    let mut subscribed: BTreeMap<u32, String> = BTreeMap::new();
    let mut received: BTreeMap<String, usize> = BTreeMap::new();
    while received.len() < 2 {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "timed out: channels {channels:?}, received {received:?}"
        );
        match ws.read() {
            Ok(Message::Text(t)) => {
                let v: Value = serde_json::from_str(&t).unwrap();
                if v["op"] == "advertise" {
                    for c in v["channels"].as_array().unwrap() {
                        channels.insert(
                            c["topic"].as_str().unwrap().into(),
                            c["id"].as_u64().unwrap(),
                        );
                    }
                }
            }
            Ok(Message::Binary(b)) => {
                // messageData: opcode 1, subscription id (u32 LE), log time, payload.
                assert_eq!(b[0], 1);
                let sub = u32::from_le_bytes([b[1], b[2], b[3], b[4]]);
                let topic = subscribed.get(&sub).cloned().unwrap_or_default();
                assert!(b.len() > 13, "{topic}: an empty message");
                *received.entry(topic).or_insert(0) += 1;
            }
            Ok(_) => {}
            Err(tungstenite::Error::Io(e))
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) => {}
            Err(e) => panic!("websocket: {e}"),
        }
        if subscribed.is_empty()
            && channels.contains_key(POINTS_TOPIC)
            && channels.contains_key(CLUSTERS_TOPIC)
        {
            let subs: Vec<Value> = [POINTS_TOPIC, CLUSTERS_TOPIC]
                .iter()
                .enumerate()
                .map(|(k, t)| {
                    subscribed.insert(k as u32 + 1, t.to_string());
                    serde_json::json!({"id": k + 1, "channelId": channels[*t]})
                })
                .collect();
            let msg = serde_json::json!({"op": "subscribe", "subscriptions": subs});
            ws.send(Message::Text(msg.to_string().into())).unwrap();
        }
        if !subscribed.is_empty() {
            server.publish(&frame);
        }
    }
    assert!(
        received.contains_key(POINTS_TOPIC) && received.contains_key(CLUSTERS_TOPIC),
        "{received:?}"
    );
    assert_eq!(server.clients(), 1);
    let _ = ws.close(None);
}

#[test]
fn a_bad_address_is_refused_with_a_reason() {
    let err = FoxgloveServer::start("nowhere").err().unwrap().to_string();
    assert!(err.contains("give HOST:PORT"), "{err}");
}
