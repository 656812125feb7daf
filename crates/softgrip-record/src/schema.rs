//! [`MsgDef`]: a `.msg` definition and the full `ros2msg` schema text that MCAP readers parse.

/// The line that separates the definitions in a `ros2msg` schema (80 `=`), as rosbag2 writes it.
pub const SCHEMA_SEPARATOR: &str =
    "================================================================================";

/// One ROS 2 message definition: its name, its `.msg` text and the definitions it uses.
#[derive(Debug)]
pub struct MsgDef {
    /// Full ROS 2 name, `pkg/msg/Type`.
    pub ros2_name: &'static str,
    /// The `.msg` file, verbatim.
    pub text: &'static str,
    /// The message types its fields use directly.
    pub dependencies: &'static [&'static MsgDef],
}

impl MsgDef {
    /// The short name `pkg/Type` used in `.msg` files and `MSG:` lines.
    pub fn short_name(&self) -> String {
        let mut parts = self.ros2_name.split('/');
        let pkg = parts.next().unwrap_or_default();
        let ty = parts.next_back().unwrap_or_default();
        format!("{pkg}/{ty}")
    }

    /// Every definition this one depends on, directly or not, once each, depth first in field
    /// order (rosbag2's order).
    pub fn all_dependencies(&self) -> Vec<&'static MsgDef> {
        fn visit(def: &MsgDef, out: &mut Vec<&'static MsgDef>) {
            for &dep in def.dependencies {
                if !out.iter().any(|d| d.ros2_name == dep.ros2_name) {
                    out.push(dep);
                    visit(dep, out);
                }
            }
        }
        let mut out = Vec::new();
        visit(self, &mut out);
        out
    }

    /// The `ros2msg` schema text: this definition, then each dependency after a separator line
    /// and a `MSG: pkg/Type` line (the layout rosbag2 and the MCAP ROS 2 profile use).
    ///
    /// ```
    /// use softgrip_record::RosMessage;
    /// use softgrip_record::msgs::geometry_msgs::Pose;
    /// let text = Pose::schema_text();
    /// assert!(text.starts_with("# A representation of pose in free space"));
    /// assert!(text.contains("\nMSG: geometry_msgs/Point\n"));
    /// assert!(text.contains("\nMSG: geometry_msgs/Quaternion\n"));
    /// ```
    pub fn schema_text(&self) -> String {
        let mut text = self.text.trim_end().to_owned();
        for dep in self.all_dependencies() {
            text.push('\n');
            text.push_str(SCHEMA_SEPARATOR);
            text.push_str("\nMSG: ");
            text.push_str(&dep.short_name());
            text.push('\n');
            text.push_str(dep.text.trim_end());
        }
        text.push('\n');
        text
    }
}
