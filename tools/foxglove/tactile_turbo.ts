// Foxglove Studio User Script (embedded in softgrip.json by make_layouts.py; edit it here).
//
// Why: Foxglove Studio 1.48's Image panel draws a `32FC1` image as value x 255 in grey, clamped
// (decodeFloat1c in @foxglove/studio-base 1.48.0), with no range and no colour map: its
// "Min/Max (depth images)" settings apply only to mono16/16UC1. A tactile image holds pressure
// in Pa (1e3..1e6), so every taxel with more than 1/255 Pa shows saturated white.
// This script republishes a tactile image as `rgb8`, colour-mapped with Turbo (Google's
// polynomial fit) over [P_MIN, P_MAX] Pa: 0 Pa is dark blue, P_MAX and above dark red.
// The `32FC1` topic itself is unchanged (it is what tools and ROS 2 nodes should read).
import { Input, Message } from "./types";

// Colour range [Pa]: the default grasp peaks at ~2.4e5 Pa (16 x 16 pads, 5 N on a 4.8 mm patch).
const P_MIN = 0;
const P_MAX = 3e5;

export const inputs = ["__INPUT__"];
export const output = "__OUTPUT__";

type Image = Message<"sensor_msgs/msg/Image">;

// Turbo colour map, t in [0, 1] -> [r, g, b] in [0, 255] (A. Mikhailov, Google, 2019, CC-BY 4.0
// polynomial approximation).
function turbo(t: number): [number, number, number] {
  const x = Math.min(Math.max(t, 0), 1);
  const x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
  const r = 0.13572138 + 4.6153926 * x - 42.66032258 * x2 + 132.13108234 * x3 - 152.94239396 * x4 + 59.28637943 * x5;
  const g = 0.09140261 + 2.19418839 * x + 4.84296658 * x2 - 14.18503333 * x3 + 4.27729857 * x4 + 2.82956604 * x5;
  const b = 0.1066733 + 12.64194608 * x - 60.58204836 * x2 + 110.36276771 * x3 - 89.90310912 * x4 + 27.34824973 * x5;
  const c = (v: number) => Math.round(255 * Math.min(Math.max(v, 0), 1));
  return [c(r), c(g), c(b)];
}

export default function node(event: Input<"__INPUT__">): Image {
  const img = event.message;
  const n = img.width * img.height;
  const src = img.data as Uint8Array;
  const view = new DataView(src.buffer, src.byteOffset, src.byteLength);
  const little = !img.is_bigendian;
  const out = new Uint8Array(n * 3);
  for (let i = 0; i < n; i++) {
    const rowStart = Math.floor(i / img.width) * img.step;
    const p = view.getFloat32(rowStart + (i % img.width) * 4, little);
    const [r, g, b] = turbo(Number.isFinite(p) ? (p - P_MIN) / (P_MAX - P_MIN) : 0);
    out[3 * i] = r;
    out[3 * i + 1] = g;
    out[3 * i + 2] = b;
  }
  return {
    header: img.header,
    height: img.height,
    width: img.width,
    encoding: "rgb8",
    is_bigendian: 0,
    step: img.width * 3,
    data: out,
  } as Image;
}
