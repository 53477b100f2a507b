#!/usr/bin/env python3
"""Decode the fixtures of this folder with the `velodyne-decoder` package
(PyPI, a decoder of its own, independent of fcc) and keep a sample of its
points as `<name>_velodyne_decoder.json`, which the tests compare fcc's
points against.

The calibrations are chosen so that both decoders model the same sensor:
- VLP-16: velodyne-decoder's built-in one (the manual's angles and vertical
  offsets, as fcc's);
- VLP-32C, HDL-32E: the calibration files it bundles (converted from
  VeloView's: angles, no origin offsets; its built-in ones approximate
  offsets the manuals do not give, fcc uses none), against fcc's own
  published tables, so the comparison checks those tables too;
- HDL-64E: `hdl64e_no_offsets.yaml`, the fixture's calibration with the origin
  offsets zeroed (velodyne-decoder applies offsets after the two-point
  correction and adds the vertical one to z; fcc follows the ROS driver).

Run from this folder after make_fixtures.py, with
`pip install velodyne-decoder==3.1.0 numpy pyyaml`:  python3 cross_check.py
"""

import json
import os

import numpy as np
import velodyne_decoder as vd
import yaml

BUNDLED = os.path.join(os.path.dirname(vd.__file__), "calibrations")


def main():
    cal = yaml.safe_load(open("hdl64e.yaml"))
    for laser in cal["lasers"]:
        laser["vert_offset_correction"] = 0.0
        laser["horiz_offset_correction"] = 0.0
    with open("hdl64e_no_offsets.yaml", "w") as f:
        f.write("# hdl64e.yaml with the origin offsets zeroed, for cross_check.py.\n")
        yaml.safe_dump(cal, f)
    runs = [
        ("vlp16", vd.Model.VLP16, None),
        ("vlp32c", vd.Model.VLP32C, os.path.join(BUNDLED, "VLP-32C.yml")),
        ("hdl32e", vd.Model.HDL32E, os.path.join(BUNDLED, "HDL-32E.yml")),
        ("hdl64e", vd.Model.HDL64E_S2, "hdl64e_no_offsets.yaml"),
    ]
    for name, model, calib in runs:
        cfg = vd.Config()
        cfg.model = model
        if calib is not None:
            cfg.calibration = vd.Calibration.read(calib)
        pts = np.concatenate([scan for _, scan in vd.read_pcap(name + ".pcap", cfg)])
        sample = pts[::41, :3].astype(float)
        out = {
            "decoder": "velodyne-decoder 3.1.0",
            "model": name,
            "calibration": None if calib is None else os.path.basename(calib),
            "points": [[round(v, 5) for v in p] for p in sample.tolist()],
        }
        with open(name + "_velodyne_decoder.json", "w") as f:
            json.dump(out, f, separators=(",", ":"))


if __name__ == "__main__":
    main()
