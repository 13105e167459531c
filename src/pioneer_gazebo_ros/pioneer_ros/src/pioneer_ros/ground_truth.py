"""What pioneer_tf_broadcaster and pioneer_odometry_publisher share: their parameters and the
/gazebo/get_model_state client they poll (the report's Listing 9, with one persistent proxy).

Parameters (private, defaults in brackets):
  ~model_name [pioneer]              the model to follow
  ~relative_entity_name [world]      get_model_state's reference frame
  ~frame_id [world]                  the parent frame of the published pose
  ~child_frame_id [base_link_truth]  the robot's frame in the published pose
  ~rate [50]                         Hz of sim time
  ~topic [/pioneer/odom_truth]       (pioneer_odometry_publisher) the nav_msgs/Odometry topic

The defaults keep clear of the drive plugin, which publishes /pioneer/odom and the tf
odom -> base_link: a second publisher of base_link's parent would make tf jump between the
two. frame_id:=odom child_frame_id:=base_link topic:=/odom gives the report's names, for use
without the drive plugin's odometry (or with its publishOdomTF false).
"""
import rospy
from gazebo_msgs.srv import GetModelState

SERVICE = '/gazebo/get_model_state'


class GroundTruthSettings:
    def __init__(self, model_name='pioneer', relative_entity_name='world', frame_id='world',
                 child_frame_id='base_link_truth', rate=50.0, topic='/pioneer/odom_truth'):
        self.model_name, self.relative_entity_name = model_name, relative_entity_name
        self.frame_id, self.child_frame_id = frame_id.lstrip('/'), child_frame_id.lstrip('/')
        self.rate, self.topic = float(rate), topic
        if not self.rate > 0.0:
            raise ValueError('~rate: expected a positive number of Hz, got %r' % rate)
        if not (self.frame_id and self.child_frame_id) or self.frame_id == self.child_frame_id:
            raise ValueError('~frame_id and ~child_frame_id: expected two different frame names, got %r and %r'
                             % (frame_id, child_frame_id))


def settings_from_params():
    d = GroundTruthSettings()
    return GroundTruthSettings(
        model_name=rospy.get_param('~model_name', d.model_name),
        relative_entity_name=rospy.get_param('~relative_entity_name', d.relative_entity_name),
        frame_id=rospy.get_param('~frame_id', d.frame_id),
        child_frame_id=rospy.get_param('~child_frame_id', d.child_frame_id),
        rate=rospy.get_param('~rate', d.rate),
        topic=rospy.get_param('~topic', d.topic))


class ModelStateClient:
    """Polls get_model_state for one model; get() is None (with a throttled warning) while
    the service or the model is missing."""

    def __init__(self, model_name, relative_entity_name):
        self.model_name, self.relative_entity_name = model_name, relative_entity_name
        rospy.loginfo('%s: waiting for %s', rospy.get_name(), SERVICE)
        rospy.wait_for_service(SERVICE)
        self._proxy = rospy.ServiceProxy(SERVICE, GetModelState, persistent=True)

    def get(self):
        try:
            response = self._proxy(model_name=self.model_name, relative_entity_name=self.relative_entity_name)
        except (rospy.ServiceException, rospy.ROSException) as e:
            rospy.logwarn_throttle(5.0, '%s: %s failed: %s' % (rospy.get_name(), SERVICE, e))
            self._proxy = rospy.ServiceProxy(SERVICE, GetModelState, persistent=True)  # reconnect
            return None
        if not response.success:
            rospy.logwarn_throttle(5.0, '%s: %s' % (rospy.get_name(), response.status_message))
            return None
        return response


def run_at_rate(rate_hz, step):
    """Calls step() at rate_hz of ROS time until shutdown; a clock jumping back (a simulation
    reset) just starts the rate over."""
    rate = rospy.Rate(rate_hz)
    while not rospy.is_shutdown():
        step()
        try:
            rate.sleep()
        except rospy.exceptions.ROSTimeMovedBackwardsException:
            rate = rospy.Rate(rate_hz)
        except rospy.ROSInterruptException:
            break
