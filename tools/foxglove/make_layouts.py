#!/usr/bin/env python3
"""Embed the User Scripts into the Foxglove layouts and point their panels at the scripts' outputs:
- softgrip.json: tactile_turbo.ts once per tactile pad (Image panels show the colour-mapped pads);
- softgrip-micro.json: contacts_micro.ts (plots of the cells' forces in uN and radii in um);
- softgrip-sphere.json (written from softgrip-micro.json): the millimetre sphere between plates
  (scenes/ecoflex_sphere.toml), grid 200 times larger, camera 400 times farther, plots in N and m;
- softgrip-hand.json, softgrip-hand3.json (written from softgrip.json): the parallel gripper's
  and the three-finger hand's scenes (scenes/robots/): the pads of HAND_TIPS / HAND3_TIPS
  (normal force per pad, tactile image per pad) and the joints' positions and efforts from
  /joint_states (two plots) in place of the contact radii.

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
# The shipped parallel gripper's pads (scenes/robots/parallel_gripper_*.toml) and the joints
# /joint_states lists for it, in its order (the URDF's).
HAND_TIPS = ["left_pad", "right_pad"]
HAND_JOINTS = ["finger_joint", "right_finger_joint"]
# The shipped three-finger hand's (scenes/robots/three_finger_hand_*.toml).
HAND3_TIPS = ["f0_pad", "f1_pad", "f2_pad"]
HAND3_JOINTS = [f"f{f}_{j}_joint" for f in range(3) for j in ("proximal", "distal")]


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


def legend_height(rows: int) -> int:
    """A plot legend's height [px] that shows `rows` series without scrolling: Foxglove 1.48's
    legend rows are 24 px, with 24 px for its margins (64 px showed 2 rows; the three-finger hand's
    force plot at 64 px hid its third pad, and its joint plots at 112 px four of six joints:
    seen with ../shared/tools/view_mcap.sh, session 15)."""
    return 24 + 24 * rows


def build_hand_for(tips: list, joints: list) -> dict:
    """softgrip.json with a hand's pads (a normal force plot and a tactile image per pad) and
    its joints (as /joint_states lists them) in two plots: positions [m or rad] and efforts
    [N or N m] (one plot for both hid the positions: 0.02 m beside -10 N)."""
    text = (HERE / "softgrip.json").read_text()
    for old, new in zip(TIPS, tips):
        text = text.replace(old, new)
    layout = json.loads(text)
    plot = layout["configById"]["Plot!force"]
    plot["sidebarDimension"] = legend_height(len(tips))
    plot["paths"] = [
        {
            "value": f'/softgrip/contacts.contacts[:]{{fingertip=="{tip}"}}.normal_force',
            "enabled": True,
            "timestampMethod": "receiveTime",
            "label": f"{tip} normal_force",
        }
        for tip in tips
    ]
    base = layout["configById"]["Plot!radius"]
    for panel, field, title in [
        ("Plot!radius", "position", "joint positions [m or rad]"),
        ("Plot!effort", "effort", "joint efforts [N or N m]"),
    ]:
        cfg = json.loads(json.dumps(base))
        cfg["paths"] = [
            {
                "value": f"/joint_states.{field}[{j}]",
                "enabled": True,
                "timestampMethod": "receiveTime",
                "label": name,
            }
            for j, name in enumerate(joints)
        ]
        cfg["title"] = title
        cfg["sidebarDimension"] = legend_height(len(joints))
        layout["configById"][panel] = cfg
    images = [f"ImageViewPanel!{tip}" for tip in tips]
    for tip in tips[len(TIPS):]:
        layout["configById"][f"ImageViewPanel!{tip}"] = dict(
            layout["configById"][f"ImageViewPanel!{tips[0]}"],
            cameraTopic=f"/studio_script/softgrip/{tip}/tactile_turbo",
        )
        layout["userNodes"][f"tactile-turbo-{tip}"] = script(tip)
    row = images[-1]
    for k in reversed(range(len(images) - 1)):
        # Equal widths: the first of the n - k images left takes 1 / (n - k) of the row.
        share = round(100.0 / (len(images) - k), 3)
        row = {"first": images[k], "second": row, "direction": "row", "splitPercentage": share}
    # The joint plots' legends are the tallest (a row per joint): they get 60 % of the plots'
    # height, the plots 68 % of the column (the 16 x 16 tactile images need little).
    layout["layout"]["second"] = {
        "first": {
            "first": "Plot!force",
            "second": {"first": "Plot!radius", "second": "Plot!effort", "direction": "row"},
            "direction": "column",
            "splitPercentage": 40,
        },
        "second": row,
        "direction": "column",
        "splitPercentage": 68,
    }
    return layout


def build_hand(_old: dict) -> dict:
    """The parallel gripper's scenes (scenes/robots/parallel_gripper_*.toml)."""
    return build_hand_for(HAND_TIPS, HAND_JOINTS)


def build_hand3(_old: dict) -> dict:
    """The three-finger hand's scenes (scenes/robots/three_finger_hand_*.toml)."""
    return build_hand_for(HAND3_TIPS, HAND3_JOINTS)


def main() -> int:
    stale = 0
    for name, build in [
        ("softgrip.json", build_default),
        ("softgrip-micro.json", build_micro),
        ("softgrip-sphere.json", build_sphere),
        ("softgrip-hand.json", build_hand),
        ("softgrip-hand3.json", build_hand3),
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
