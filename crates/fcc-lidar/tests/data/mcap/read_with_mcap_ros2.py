#!/usr/bin/env python3
"""Decode an MCAP file with the third-party `mcap-ros2-support` decoder and
print, per message, one JSON line: topic, schema, log time, header stamp
and what the message holds (a PointCloud2's fields, point count and the
labels of its points; a MarkerArray's markers). The tests of the MCAP sink
compare these lines with what they wrote.

    python3 read_with_mcap_ros2.py FILE.mcap
"""

import json
import struct
import sys

from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory


def main(path):
    with open(path, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        for schema, channel, message, msg in reader.iter_decoded_messages():
            out = {
                "topic": channel.topic,
                "schema": schema.name,
                "log_time": message.log_time,
            }
            if schema.name == "sensor_msgs/msg/PointCloud2":
                out["stamp"] = [msg.header.stamp.sec, msg.header.stamp.nanosec]
                out["frame_id"] = msg.header.frame_id
                out["fields"] = [[x.name, x.offset, x.datatype, x.count] for x in msg.fields]
                out["width"] = msg.width
                data = bytes(msg.data)
                pts = [
                    struct.unpack_from("<fffI", data, k * msg.point_step)
                    for k in range(msg.width)
                ]
                out["points"] = [[p[0], p[1], p[2]] for p in pts]
                out["labels"] = [p[3] for p in pts]
            elif schema.name == "visualization_msgs/msg/MarkerArray":
                out["markers"] = [
                    {
                        "id": m.id,
                        "type": m.type,
                        "action": m.action,
                        "stamp": [m.header.stamp.sec, m.header.stamp.nanosec],
                        "position": [m.pose.position.x, m.pose.position.y, m.pose.position.z],
                        "orientation": [
                            m.pose.orientation.x,
                            m.pose.orientation.y,
                            m.pose.orientation.z,
                            m.pose.orientation.w,
                        ],
                        "scale": [m.scale.x, m.scale.y, m.scale.z],
                        "text": m.text,
                    }
                    for m in msg.markers
                ]
            print(json.dumps(out))


if __name__ == "__main__":
    main(sys.argv[1])
