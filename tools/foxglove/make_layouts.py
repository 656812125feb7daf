#!/usr/bin/env python3
"""Embed tactile_turbo.ts into softgrip.json as one Foxglove User Script per tactile pad, and point
the layout's Image panels at the scripts' colour-mapped outputs.

usage: python3 tools/foxglove/make_layouts.py          # rewrite softgrip.json in place
       python3 tools/foxglove/make_layouts.py --check  # exit 1 if softgrip.json is stale

The pads are the default scene's (scenes/default.toml): left_tip and right_tip. For another
scene, add its fingertip names to TIPS (a fingertip named like its body is recorded as
`<name>_tip`; see the recording's /tf_static).
"""
import json
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
TIPS = ["left_tip", "right_tip"]


def script(tip: str) -> dict:
    src = (HERE / "tactile_turbo.ts").read_text()
    src = src.replace("__INPUT__", f"/softgrip/{tip}/tactile")
    src = src.replace("__OUTPUT__", f"/studio_script/softgrip/{tip}/tactile_turbo")
    return {"name": f"{tip} tactile turbo", "sourceCode": src}


def build(layout: dict) -> dict:
    layout["userNodes"] = {f"tactile-turbo-{tip}": script(tip) for tip in TIPS}
    for tip in TIPS:
        topic = f"/studio_script/softgrip/{tip}/tactile_turbo"
        layout["configById"][f"ImageViewPanel!{tip}"] = {
            "cameraTopic": topic,
            "enabledMarkerTopics": [],
            "mode": "fit",
            "smooth": False,
            "synchronize": False,
            "transformMarkers": False,
        }
    return layout


def main() -> int:
    path = HERE / "softgrip.json"
    old = path.read_text()
    new = json.dumps(build(json.loads(old)), indent=1) + "\n"
    if "--check" in sys.argv:
        if new != old:
            print(f"{path} is stale: run python3 {pathlib.Path(__file__).name}", file=sys.stderr)
            return 1
        return 0
    path.write_text(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
