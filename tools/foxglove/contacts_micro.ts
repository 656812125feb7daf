// Foxglove Studio User Script (embedded in softgrip-micro.json by make_layouts.py; edit it here).
//
// Why: Foxglove Studio 1.48's Plot panel rounds its y ticks to 3 decimals (chart.js
// `ticks.precision: 3`), so a cell's forces (~3e-5 N) and patch radii (~2e-5 m) are drawn on an
// axis from 0 to 0.001 as a flat line at 0, whatever the y range. This script republishes each
// contact of /softgrip/contacts in micro units, which the Plot panel labels well:
// force [uN], lengths [um], pressure [kPa]. Nothing is recomputed: each value is the recorded
// one times a power of ten.
import { Input } from "./types";

export const inputs = ["/softgrip/contacts"];
export const output = "/studio_script/softgrip/contacts_micro";

type MicroContact = {
  fingertip: string;
  other: string;
  /** Normal force [uN]. */
  normal_force_un: number;
  /** Peak normal force over the step [uN]. */
  peak_normal_force_un: number;
  /** Contact (patch) radius a [um]. */
  contact_radius_um: number;
  /** Compression delta [um]. */
  compression_um: number;
  /** Largest compression over the step [um]. */
  max_compression_um: number;
  /** x = delta / R [-] (unchanged). */
  ratio_x: number;
  /** Mean pressure [kPa]. */
  mean_pressure_kpa: number;
};

type Output = { contacts: MicroContact[] };

export default function node(event: Input<"/softgrip/contacts">): Output {
  return {
    contacts: event.message.contacts.map((c) => ({
      fingertip: c.fingertip,
      other: c.other,
      normal_force_un: c.normal_force * 1e6,
      peak_normal_force_un: c.peak_normal_force * 1e6,
      contact_radius_um: c.contact_radius * 1e6,
      compression_um: c.compression * 1e6,
      max_compression_um: c.max_compression * 1e6,
      ratio_x: c.ratio_x,
      mean_pressure_kpa: c.mean_pressure * 1e-3,
    })),
  };
}
