#pragma once
// A publisher that knows whether anyone subscribes without asking roscpp every step.
// ros::Publisher::getNumSubscribers() takes roscpp's locks and looks the topic up by name: a
// microsecond or so, which is a fifth of a physics step, and sensors and the /gazebo topics ask it
// every step to skip work nobody reads. The count here follows roscpp's connect and disconnect
// callbacks, which arrive through the node's callback queue (so on the simulator's thread).
#include <ros/ros.h>

#include "publish_thread/publish_thread.h"

#include <memory>
#include <string>

namespace bullet_sim {

class CountedPublisher {
 public:
  template <class Message>
  void advertise(ros::NodeHandle& node, const std::string& topic, int queue_size) {
    auto count = subscribers_;
    publisher_ = node.advertise<Message>(
        topic, queue_size, [count](const ros::SingleSubscriberPublisher&) { ++*count; },
        [count](const ros::SingleSubscriberPublisher&) { --*count; });
  }
  bool hasSubscribers() const { return *subscribers_ > 0; }
  // From the process's publishing thread (publish_thread.h).
  template <class Message>
  void publish(Message message) const {
    publish_thread::publish(publisher_, std::move(message));
  }
  std::string getTopic() const { return publisher_.getTopic(); }

 private:
  ros::Publisher publisher_;
  std::shared_ptr<int> subscribers_ = std::make_shared<int>(0);  // shared with the callbacks
};

}  // namespace bullet_sim
