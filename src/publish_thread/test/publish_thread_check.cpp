// rostest (test/publish_thread.test). With --publish N: the publisher process of the test. Without:
// the gtest, which subscribes from another process and checks what arrives.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/UInt32.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

#include "publish_thread/publish_thread.h"

namespace {

// Hands n numbered messages to the publishing thread, alternating /numbers_a and /numbers_b, once
// both have a subscriber; then stays up until shut down.
int publishNumbered(std::uint32_t n) {
  ros::NodeHandle node;
  // Room for every message: a burst larger than a publisher's queue is dropped by roscpp itself.
  ros::Publisher a = node.advertise<std_msgs::UInt32>("/numbers_a", n);
  ros::Publisher b = node.advertise<std_msgs::UInt32>("/numbers_b", n);
  while (ros::ok() && (a.getNumSubscribers() == 0 || b.getNumSubscribers() == 0)) ros::WallDuration(0.01).sleep();
  for (std::uint32_t k = 0; k < n && ros::ok(); ++k) {
    std_msgs::UInt32 message;
    message.data = k;
    publish_thread::publish(k % 2 == 0 ? a : b, message);
  }
  publish_thread::instance().flush();
  ROS_INFO("handed over and published %lu messages", static_cast<unsigned long>(publish_thread::instance().published()));
  ros::spin();
  return 0;
}

struct Received {
  std::mutex mutex;
  std::vector<std::uint32_t> a, b;
  std::size_t size() {
    std::lock_guard<std::mutex> lock(mutex);
    return a.size() + b.size();
  }
};

TEST(PublishThread, EveryMessageArrivesInOrderOnItsTopic) {
  ros::NodeHandle node;
  Received received;
  auto record = [&received](std::vector<std::uint32_t>& into, const std_msgs::UInt32& m) {
    std::lock_guard<std::mutex> lock(received.mutex);
    into.push_back(m.data);
  };
  ros::Subscriber sa = node.subscribe<std_msgs::UInt32>(
      "/numbers_a", 5000, [&](const std_msgs::UInt32::ConstPtr& m) { record(received.a, *m); });
  ros::Subscriber sb = node.subscribe<std_msgs::UInt32>(
      "/numbers_b", 5000, [&](const std_msgs::UInt32::ConstPtr& m) { record(received.b, *m); });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (received.size() < 2000 && ros::WallTime::now() < deadline) ros::WallDuration(0.01).sleep();
  ros::WallDuration(0.2).sleep();  // anything beyond the 2000 would show now
  std::lock_guard<std::mutex> lock(received.mutex);
  ASSERT_EQ(received.a.size(), 1000u);
  ASSERT_EQ(received.b.size(), 1000u);
  for (std::uint32_t k = 0; k < 1000; ++k) {
    ASSERT_EQ(received.a[k], 2 * k) << "message " << k << " of /numbers_a";
    ASSERT_EQ(received.b[k], 2 * k + 1) << "message " << k << " of /numbers_b";
  }
}

TEST(PublishThread, FlushReturnsOnceEverythingHandedOverIsPublished) {
  ros::NodeHandle node;
  ros::Publisher p = node.advertise<std_msgs::UInt32>("/flushed", 10);
  publish_thread::PublishThread thread;
  for (std::uint32_t k = 0; k < 500; ++k) {
    std_msgs::UInt32 message;
    message.data = k;
    thread.publish(p, message);
  }
  thread.flush();
  EXPECT_EQ(thread.published(), 500u);
  // Again after the thread has gone to sleep (no message for 10 ms): the next one wakes it.
  ros::WallDuration(0.05).sleep();
  thread.publish(p, std_msgs::UInt32());
  thread.flush();
  EXPECT_EQ(thread.published(), 501u);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "--publish") == 0) {
    ros::init(argc, argv, "numbered_publisher");
    return publishNumbered(static_cast<std::uint32_t>(std::atoi(argv[2])));
  }
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "publish_thread_check");
  return RUN_ALL_TESTS();
}
