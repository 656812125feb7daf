#!/usr/bin/env python3
"""Embed the User Scripts into the Foxglove layouts and point their panels at the scripts' outputs:
- softgrip.json: tactile_turbo.ts once per tactile pad (Image panels show the colour-mapped pads);
- softgrip-micro.json: contacts_micro.ts (plots of the cells' forces in uN and radii in um);
- softgrip-sphere.json (written from softgrip-micro.json): the millimetre sphere between plates
  (scenes/ecoflex_sphere.toml), grid 200 times larger, camera 400 times farther, plots in N and m;
- softgrip-hand.json (written from softgrip.json): hand scenes (scenes/robots/), the pads of
  HAND_TIPS (normal force per pad, tactile image per pad) and the joints' positions and efforts
  from /joint_states in place of the contact radii.

usage: python3 tools/foxglove/make_layouts.py          # rewrite both layouts in place
       python3 tools/foxglove/make_layouts.py --check  # exit 1 if a layout is stale

The pads are the default scene's (scenes/default.toml): left_tip and right_tip. For another
scene, add its fingertip names to TIPS (a fingertip named like its body is recorded as
`<name>_tip`; see the recording's /tf_static).
"""
import json
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
TIPS = ["left_tip", "right_tip"]
# The shipped parallel gripper's pads (scenes/robots/parallel_gripper_box.toml) and how many
# joints /joint_states lists for it (finger_joint and its mimic).
HAND_TIPS = ["left_pad", "right_pad"]
HAND_JOINTS = 2


def script(tip: str) -> dict:
    src = (HERE / "tactile_turbo.ts").read_text()
    src = src.replace("__INPUT__", f"/softgrip/{tip}/tactile")
    src = src.replace("__OUTPUT__", f"/studio_script/softgrip/{tip}/tactile_turbo")
    return {"name": f"{tip} tactile turbo", "sourceCode": src}


def build_default(layout: dict) -> dict:
    layout["userNodes"] = {f"tactile-turbo-{tip}": script(tip) for tip in TIPS}
    for panel in ("Plot!force", "Plot!radius"):
        layout["configById"][panel]["sidebarDimension"] = 64  # the legend: 2 rows, not half the plot
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


MICRO_TOPIC = "/studio_script/softgrip/contacts_micro"
# (panel, field, title); every plot's y axis starts at 0 (minYValue).
MICRO_PLOTS = [
    ("Plot!force", "normal_force_un", "normal force [uN]"),
    ("Plot!radius", "contact_radius_um", "contact radius [um]"),
]


def build_micro(layout: dict) -> dict:
    layout["userNodes"] = {
        "contacts-micro": {
            "name": "contacts in uN and um",
            "sourceCode": (HERE / "contacts_micro.ts").read_text(),
        }
    }
    for panel, field, title in MICRO_PLOTS:
        cfg = layout["configById"][panel]
        cfg["paths"] = [
            {
                "value": f'{MICRO_TOPIC}.contacts[:]{{fingertip=="sphere"}}.{field}',
                "enabled": True,
                "timestampMethod": "receiveTime",
                "label": f"sphere {field}",
            }
        ]
        cfg["title"] = title
        cfg["minYValue"] = 0
        cfg["sidebarDimension"] = 40
    return layout


def build_sphere(_old: dict) -> dict:
    """The micro layout scaled up 200 times (R = 5 mm vs the cells' 14-16 um), raw N and m."""
    layout = build_micro(json.loads((HERE / "softgrip-micro.json").read_text()))
    del layout["userNodes"]
    k = 200.0
    cam = layout["configById"]["3D!grasp"]["cameraState"]
    for key in ("distance", "near", "far"):
        cam[key] = round(cam[key] * 2 * k, 12)  # twice as far: a patch grows to 1.6 R
    tf = layout["configById"]["3D!grasp"]["scene"]["transforms"]
    for key in ("labelSize", "axisScale"):
        tf[key] = round(tf[key] * k, 12)
    grid = layout["configById"]["3D!grasp"]["layers"]["grid"]
    grid["size"] = round(grid["size"] * k, 12)
    for panel, field, title in [
        ("Plot!force", "normal_force", "normal force [N]"),
        ("Plot!radius", "contact_radius", "contact radius [m]"),
    ]:
        cfg = layout["configById"][panel]
        cfg["paths"][0]["value"] = f'/softgrip/contacts.contacts[:]{{fingertip=="sphere"}}.{field}'
        cfg["paths"][0]["label"] = f"sphere {field}"
        cfg["title"] = title
    return layout


def build_hand(_old: dict) -> dict:
    """softgrip.json with HAND_TIPS' pads, and the joints' positions and efforts."""
    text = (HERE / "softgrip.json").read_text()
    for old, new in zip(TIPS, HAND_TIPS):
        text = text.replace(old, new)
    layout = json.loads(text)
    cfg = layout["configById"]["Plot!radius"]
    cfg["paths"] = [
        {
            "value": f"/joint_states.{field}[{j}]",
            "enabled": True,
            "timestampMethod": "receiveTime",
            "label": f"joint {j} {field}",
        }
        for field in ("position", "effort")
        for j in range(HAND_JOINTS)
    ]
    cfg["title"] = "joints: position [m or rad], effort [N or N m]"
    return layout


def main() -> int:
    stale = 0
    for name, build in [
        ("softgrip.json", build_default),
        ("softgrip-micro.json", build_micro),
        ("softgrip-sphere.json", build_sphere),
        ("softgrip-hand.json", build_hand),
    ]:
        path = HERE / name
        old = path.read_text() if path.exists() else "{}"
        new = json.dumps(build(json.loads(old)), indent=1) + "\n"
        if "--check" in sys.argv:
            if new != old:
                print(f"{path} is stale: run python3 {pathlib.Path(__file__).name}", file=sys.stderr)
                stale = 1
        else:
            path.write_text(new)
    return stale


if __name__ == "__main__":
    sys.exit(main())
