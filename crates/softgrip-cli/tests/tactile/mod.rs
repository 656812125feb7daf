//! The tactile images of a recording of the default scene (16 x 16 pads, 1 mm taxels): each
//! decoded by Python's `mcap-ros2-support` as softgrip decodes it (`32FC1`, little-endian,
//! `step = 4 columns`, frame = the fingertip), and `Σ pressure x taxel area` equal to the
//! normal force of the fingertip's contacts of the same step within 1 %.

use std::collections::HashMap;

use serde_json::Value;
use softgrip_record::msgs::sensor_msgs::Image;
use softgrip_record::msgs::softgrip_msgs::SoftContactArrayMsg;

/// Taxel area of the default scene's pads: (16 mm / 16)^2 [m^2].
const TAXEL_AREA: f64 = 1e-6;

/// What the images of a recording showed.
#[derive(Default)]
pub struct Images {
    /// Per fingertip: the step's normal force [N], and whether every contact has a patch.
    force: HashMap<String, (f64, bool)>,
    checked: usize,
    compared: usize,
    worst: f64,
}

impl Images {
    /// The step's contacts (they come before its images).
    pub fn contacts(&mut self, a: &SoftContactArrayMsg) {
        self.force.clear();
        for c in &a.contacts {
            let e = self.force.entry(c.fingertip.clone()).or_insert((0.0, true));
            e.0 += c.normal_force;
            e.1 &= c.contact_radius > 0.0;
        }
    }

    /// One image: Python's decoding against softgrip's, and its integral against the force.
    pub fn check(&mut self, topic: &str, py: &Value, img: &Image) {
        let tip = topic
            .strip_prefix("/softgrip/")
            .and_then(|t| t.strip_suffix("/tactile"))
            .unwrap_or_else(|| panic!("not a tactile topic: {topic}"));
        assert_eq!(py["encoding"], "32FC1");
        assert_eq!(py["is_bigendian"], 0);
        assert_eq!(
            (py["height"].as_u64(), py["width"].as_u64()),
            (Some(16), Some(16))
        );
        assert_eq!(py["step"].as_u64(), Some(64));
        assert_eq!(py["header"]["frame_id"], tip);
        let bytes: Vec<u8> = py["data"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b.as_u64().unwrap() as u8)
            .collect();
        assert_eq!(bytes, img.data, "{topic}: python's bytes");
        let p = img.pixels_f32();
        assert_eq!(p.len(), 256);
        assert!(p.iter().all(|v| v.is_finite() && *v >= 0.0));
        let total: f64 = p.iter().map(|v| *v as f64).sum::<f64>() * TAXEL_AREA;
        let (force, patches) = self.force.get(tip).copied().unwrap_or((0.0, true));
        if force == 0.0 {
            assert_eq!(total, 0.0, "{topic}: pressure without contact");
        } else if force > 0.01 && patches {
            let err = (total / force - 1.0).abs();
            assert!(err < 0.01, "{topic}: Σ p A = {total} N vs F = {force} N");
            self.worst = self.worst.max(err);
            self.compared += 1;
        }
        self.checked += 1;
    }

    /// Every step had both images; most were compared with the force.
    pub fn finish(&self, steps: usize) {
        println!(
            "tactile images: {} decoded, {} compared with the normal force, worst |Σ p A / F - 1| = {:.2e}",
            self.checked, self.compared, self.worst
        );
        assert_eq!(self.checked, 2 * steps);
        assert!(self.compared > 200, "{}", self.compared);
    }
}
