//! [`ControllerRecord`]: one controller of the run, as written in the recording's metadata.

use std::fmt;

use serde::{Deserialize, Serialize};

/// One controller of the run, as recorded (the `controllers` value of the `softgrip`
/// metadata, in the order the controllers run): its name, its kind's name and its kind's
/// fixed code, both from the one table of controller kinds (`softgrip_scene::CONTROLLERS`;
/// this crate does not read the scene, the code that fills [`SceneInfo`](crate::SceneInfo)
/// copies the row). A code keeps its meaning for ever: a reader may go by either.
///
/// ```
/// use softgrip_record::ControllerRecord;
/// let c = ControllerRecord { name: "gripper".into(), kind: "parallel_jaws".into(), code: 0 };
/// let json = serde_json::to_string(&c).unwrap();
/// assert_eq!(json, r#"{"name":"gripper","kind":"parallel_jaws","code":0}"#);
/// assert_eq!(serde_json::from_str::<ControllerRecord>(&json).unwrap(), c);
/// assert_eq!(c.to_string(), "gripper: parallel_jaws (code 0)");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct ControllerRecord {
    /// The controller's name (unique in the scene).
    pub name: String,
    /// Its kind's name (a scene file's `[[controller]] type`, or `joint_commands`).
    pub kind: String,
    /// Its kind's fixed code in files (0..=255; never reused for another kind).
    pub code: u8,
}

impl fmt::Display for ControllerRecord {
    /// `NAME: KIND (code CODE)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {} (code {})", self.name, self.kind, self.code)
    }
}
