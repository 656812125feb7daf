//! The participant and node softgrip creates, and topics named as the recording names them.

use ros2_client::{Context, ContextOptions, MessageTypeName, Node, NodeName, QosProfile};
use softgrip_record::RosMessage;

use crate::domain::{MAX_DOMAIN_ID, domain_id_from_env};
use crate::error::{Error, Result};

/// Where a publisher or subscriber joins the ROS graph.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeOptions {
    /// ROS domain id in `0..=232`; `None` (the default) reads `ROS_DOMAIN_ID` (unset or empty:
    /// 0), as ROS 2 nodes do.
    pub domain_id: Option<u16>,
    /// Node name, a ROS name token. Default `softgrip`.
    pub name: String,
    /// Node namespace, absolute. Default `/`. Topics are absolute (`/softgrip/...`, `/tf`), so
    /// the namespace does not change them.
    pub namespace: String,
}

impl Default for NodeOptions {
    fn default() -> Self {
        Self {
            domain_id: None,
            name: "softgrip".into(),
            namespace: "/".into(),
        }
    }
}

impl NodeOptions {
    /// The domain id: the one given (checked) or `ROS_DOMAIN_ID`'s.
    pub fn resolve_domain_id(&self) -> Result<u16> {
        match self.domain_id {
            Some(id) if id <= MAX_DOMAIN_ID => Ok(id),
            Some(id) => Err(Error::DomainId {
                value: id.to_string(),
            }),
            None => domain_id_from_env(),
        }
    }
}

/// A DDS participant on the options' domain (ros2-client's `Context::new` would use domain 0
/// whatever `ROS_DOMAIN_ID` says) and a node without rosout or parameter services (softgrip
/// neither logs to `/rosout` nor has parameters; fewer endpoints, less discovery traffic).
pub(crate) fn create_node(options: &NodeOptions) -> Result<(Context, Node, u16)> {
    let domain_id = options.resolve_domain_id()?;
    let context =
        Context::with_options(ContextOptions::new().domain_id(domain_id)).map_err(|e| {
            Error::Context {
                domain_id,
                reason: e.to_string(),
            }
        })?;
    let node_err = |reason: String| Error::Node {
        node: format!(
            "{}/{}",
            options.namespace.trim_end_matches('/'),
            options.name
        ),
        reason,
    };
    let name =
        NodeName::new(&options.namespace, &options.name).map_err(|e| node_err(e.to_string()))?;
    let node = context
        .new_node(
            name,
            ros2_client::NodeOptions::new()
                .enable_rosout(false)
                .start_parameter_services(false),
        )
        .map_err(|e| node_err(e.to_string()))?;
    Ok((context, node, domain_id))
}

/// The DDS topic name of an absolute ROS topic: `rt` + the name (`/tf` -> `rt/tf`).
///
/// ```
/// assert_eq!(softgrip_ros2::dds_topic_name("/softgrip/contacts"), "rt/softgrip/contacts");
/// ```
pub fn dds_topic_name(ros_topic: &str) -> String {
    format!("rt/{}", ros_topic.trim_start_matches('/'))
}

/// The DDS type name of a ROS message type: `pkg/msg/Type` -> `pkg::msg::dds_::Type_`.
///
/// ```
/// use softgrip_record::RosMessage;
/// use softgrip_record::msgs::geometry_msgs::WrenchStamped;
/// assert_eq!(
///     softgrip_ros2::dds_type_name::<WrenchStamped>(),
///     "geometry_msgs::msg::dds_::WrenchStamped_"
/// );
/// ```
pub fn dds_type_name<M: RosMessage>() -> String {
    message_type_name::<M>().dds_msg_type()
}

fn message_type_name<M: RosMessage>() -> MessageTypeName {
    let mut parts = M::TYPE_NAME.split('/');
    let package = parts.next().unwrap_or_default();
    let name = parts.next_back().unwrap_or_default();
    MessageTypeName::new(package, name)
}

/// The topic `ros_topic` (absolute) of type `M`. The DDS name is made here rather than by
/// ros2-client's `Name`, which rejects some names the recording uses (e.g. a `__` that
/// [`softgrip_record::topics::wrench`] makes of `"a  b"`): live topics stay the recording's.
pub(crate) fn create_topic<M: RosMessage>(
    context: &Context,
    ros_topic: &str,
    qos: &QosProfile,
) -> Result<ros2_client::dds::rustdds::Topic> {
    context
        .create_topic(dds_topic_name(ros_topic), message_type_name::<M>(), qos)
        .map_err(|e| Error::Endpoint {
            what: "topic",
            topic: ros_topic.to_owned(),
            reason: e.to_string(),
        })
}
