//! [`GripperActionServer`]: a `control_msgs/action/ParallelGripperCommand` action server (what
//! MoveIt and ros2_controllers' `parallel_gripper_action_controller` speak), polled from a
//! thread of the caller's: goals in, feedback and results out. What a goal does is the caller's.
//!
//! The message types are ROS 2 Kilted's `control_msgs/action/ParallelGripperCommand` (control_msgs
//! 5.x), field for field, so their CDR is the same:
//!
//! ```text
//! sensor_msgs/JointState command      # goal: name, position, velocity (max), effort (max)
//! ---
//! sensor_msgs/JointState state        # result
//! bool stalled
//! bool reached_goal
//! ---
//! sensor_msgs/JointState state        # feedback
//! ```

use std::collections::HashMap;

use ros2_client::RmwRequestId;
use ros2_client::action::{
    ActionServer, ActionServerQosPolicies, GetResultResponse, GoalId, GoalInfo, GoalStatusEnum,
    SendGoalResponse,
};
use ros2_client::action_msgs::{GoalStatus, GoalStatusArray};
use ros2_client::builtin_interfaces::Time;
use ros2_client::{ActionTypeName, Context, Message, Name, Node, ServiceMapping};
use serde::{Deserialize, Serialize};
use softgrip_record::msgs::sensor_msgs::JointState;

use crate::error::{Error, Result};
use crate::node::{NodeOptions, create_node};
use crate::qos;

/// The action's ROS type: `control_msgs/action/ParallelGripperCommand`.
pub const GRIPPER_ACTION_TYPE: (&str, &str) = ("control_msgs", "ParallelGripperCommand");

/// The last segment of a gripper action's name: `/<group>/gripper_cmd`, as
/// `parallel_gripper_action_controller` names its action (`~/gripper_cmd`).
pub const GRIPPER_ACTION_SUFFIX: &str = "gripper_cmd";

/// `ParallelGripperCommand_Goal`: the command, a `JointState` (each named joint's target
/// `position` \[m or rad\]; `velocity`, if given, its largest speed \[m/s or rad/s\]; `effort`,
/// if given, its largest effort \[N or N m\]).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ParallelGripperGoal {
    /// The command.
    pub command: JointState,
}
impl Message for ParallelGripperGoal {}

/// `ParallelGripperCommand_Result`: the joints' state at the end, whether they stopped short
/// (`stalled`) or reached the target (`reached_goal`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ParallelGripperResult {
    /// The joints' state at the end.
    pub state: JointState,
    /// The joints stopped short of the target, held (by contact or their effort limit).
    pub stalled: bool,
    /// Every joint is at its target.
    pub reached_goal: bool,
}
impl Message for ParallelGripperResult {}

/// `ParallelGripperCommand_Feedback`: the joints' state while the goal runs.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ParallelGripperFeedback {
    /// The joints' state.
    pub state: JointState,
}
impl Message for ParallelGripperFeedback {}

/// A goal's id as a number (its UUID's 128 bits).
pub type GoalKey = u128;

/// A goal's bookkeeping: its status, when accepted, its result once ended, and who asked.
struct Goal {
    id: GoalId,
    status: GoalStatusEnum,
    accepted: Time,
    result: Option<ParallelGripperResult>,
    waiting: Vec<RmwRequestId>,
}

/// Serves `control_msgs/action/ParallelGripperCommand` at `/<group>/gripper_cmd`, with its own
/// DDS participant. Nothing waits: call [`poll`](Self::poll) often (every few ms) from one
/// thread; it answers result requests and publishes statuses.
pub struct GripperActionServer {
    server: ActionServer<ParallelGripperGoal, ParallelGripperResult, ParallelGripperFeedback>,
    goals: HashMap<GoalKey, Goal>,
    name: String,
    domain_id: u16,
    // Field order is drop order: the server goes before the node and the context.
    _node: Node,
    _context: Context,
}

impl std::fmt::Debug for GripperActionServer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GripperActionServer")
            .field("name", &self.name)
            .field("domain_id", &self.domain_id)
            .finish_non_exhaustive()
    }
}

impl GripperActionServer {
    /// Joins the domain and serves the action `/<group>/gripper_cmd`. `group` must be a ROS
    /// name token (letters, digits, `_`; not starting with a digit), else [`Error::Endpoint`].
    pub fn new(options: &NodeOptions, group: &str) -> Result<Self> {
        let name = format!("/{group}/{GRIPPER_ACTION_SUFFIX}");
        let endpoint = |reason: String| Error::Endpoint {
            what: "action server",
            topic: name.clone(),
            reason,
        };
        let action = Name::new(&format!("/{group}"), GRIPPER_ACTION_SUFFIX)
            .map_err(|e| endpoint(format!("`{group}` is not a ROS name token: {e}")))?;
        let (context, mut node, domain_id) = create_node(options)?;
        let policies = ActionServerQosPolicies {
            goal_service: qos::data(),
            result_service: qos::data(),
            cancel_service: qos::data(),
            feedback_publisher: qos::data(),
            // rcl_action's status QoS: reliable, keep last 1, transient local.
            status_publisher: qos::tf_static(),
        };
        let (package, kind) = GRIPPER_ACTION_TYPE;
        let server = node
            .create_action_server(
                // rmw_fastrtps's mapping (ROS 2's default middleware); a client that sends no
                // request identity still gets its reply (the sample's own identity is used).
                ServiceMapping::Enhanced,
                &action,
                &ActionTypeName::new(package, kind),
                policies,
            )
            .map_err(|e| endpoint(e.to_string()))?;
        Ok(Self {
            server,
            goals: HashMap::new(),
            name,
            domain_id,
            _node: node,
            _context: context,
        })
    }

    /// The action's name (`/<group>/gripper_cmd`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The ROS domain id in use.
    pub fn domain_id(&self) -> u16 {
        self.domain_id
    }

    /// Takes the next goal sent, if any, and answers it: `decide` gets the goal's command and
    /// returns whether to accept it. An accepted goal is executing from now on; its key is
    /// returned with the command.
    pub fn take_goal(
        &mut self,
        decide: impl FnOnce(&JointState) -> bool,
    ) -> Result<Option<(GoalKey, JointState)>> {
        let Some((request_id, request)) = self.server.receive_goal().map_err(|e| self.read(e))?
        else {
            return Ok(None);
        };
        let accepted = decide(&request.goal.command);
        let stamp = Time::now();
        let response = SendGoalResponse { accepted, stamp };
        // A client that left before its answer is no error of ours.
        let _ = self.server.send_goal_response(request_id, response);
        if !accepted {
            return Ok(None);
        }
        let key = request.goal_id.uuid.as_u128();
        self.goals.insert(
            key,
            Goal {
                id: request.goal_id,
                status: GoalStatusEnum::Executing,
                accepted: stamp,
                result: None,
                waiting: Vec::new(),
            },
        );
        self.publish_statuses();
        Ok(Some((key, request.goal.command)))
    }

    /// Sends `state` as goal `key`'s feedback (nothing if the goal is not executing).
    pub fn feedback(&self, key: GoalKey, state: JointState) {
        if let Some(g) = self.goals.get(&key)
            && g.status == GoalStatusEnum::Executing
        {
            let _ = self
                .server
                .send_feedback(g.id, ParallelGripperFeedback { state });
        }
    }

    /// Ends goal `key` with `result` (succeeded if it reached the goal, aborted otherwise, as
    /// `parallel_gripper_action_controller` does) and answers whoever asked for its result.
    pub fn finish(&mut self, key: GoalKey, result: ParallelGripperResult) {
        let Some(g) = self.goals.get_mut(&key) else {
            return;
        };
        g.status = if result.reached_goal {
            GoalStatusEnum::Succeeded
        } else {
            GoalStatusEnum::Aborted
        };
        for request_id in std::mem::take(&mut g.waiting) {
            let _ = self.server.send_result(
                request_id,
                GetResultResponse {
                    status: g.status,
                    result: result.clone(),
                },
            );
        }
        g.result = Some(result);
        self.publish_statuses();
    }

    /// Answers result requests (at once for an ended goal, at its end otherwise) and refuses
    /// cancel requests (a gripper goal runs to its end or is replaced by the next one). Call
    /// it often.
    pub fn poll(&mut self) -> Result<()> {
        while let Some((request_id, request)) = self
            .server
            .receive_result_request()
            .map_err(|e| self.read(e))?
        {
            match self.goals.get_mut(&request.goal_id.uuid.as_u128()) {
                Some(g) => match &g.result {
                    Some(result) => {
                        let _ = self.server.send_result(
                            request_id,
                            GetResultResponse {
                                status: g.status,
                                result: result.clone(),
                            },
                        );
                    }
                    None => g.waiting.push(request_id),
                },
                None => {
                    let _ = self.server.send_result(
                        request_id,
                        GetResultResponse {
                            status: GoalStatusEnum::Unknown,
                            result: ParallelGripperResult::default(),
                        },
                    );
                }
            }
        }
        while let Some((request_id, _)) = self
            .server
            .receive_cancel_request()
            .map_err(|e| self.read(e))?
        {
            // ERROR_REJECTED (1), no goal canceling.
            let _ = self.server.send_cancel_response(
                request_id,
                ros2_client::action_msgs::CancelGoalResponse {
                    return_code: ros2_client::action_msgs::CancelGoalResponseEnum::Rejected,
                    goals_canceling: Vec::new(),
                },
            );
        }
        Ok(())
    }

    fn publish_statuses(&self) {
        let status_list = (self.goals.values())
            .map(|g| GoalStatus {
                goal_info: GoalInfo {
                    goal_id: g.id,
                    stamp: g.accepted,
                },
                status: g.status,
            })
            .collect();
        let _ = self
            .server
            .send_goal_statuses(GoalStatusArray { status_list });
    }

    fn read(&self, e: impl std::fmt::Display) -> Error {
        Error::Read {
            topic: self.name.clone(),
            reason: e.to_string(),
        }
    }
}
