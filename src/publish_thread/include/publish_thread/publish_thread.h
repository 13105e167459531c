#pragma once
// Publishing from a thread of its own.
//
// A ros::Publisher::publish() costs its caller 6-10 us on our 2-core VMs, mostly roscpp waking
// its I/O thread (a wake-up on another CPU) for every message. A simulator running unthrottled
// publishes ten thousand messages a second (/clock, scans, joint states), which then costs more
// than its physics. So the loop hands each message over (a lock and a move) and one thread per
// process publishes them, in the order they were handed over. It takes whatever has been handed
// over since it last looked, publishes it, and looks again; finding nothing, it polls every 0.5 ms
// (as realtime_tools' RealtimePublisher does), so a loop that keeps publishing never has to wake
// it, and after 10 ms without a message it sleeps until the next one wakes it.
//
// Every message handed over is published, none is dropped or merged (unlike RealtimePublisher).
// Delivery is later by at most a poll period, and in order across all topics of the process.
#include <ros/publisher.h>

#include <boost/make_shared.hpp>

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace publish_thread {

class PublishThread {
 public:
  PublishThread();
  // Publishes what is still queued (while ROS is up), then stops.
  ~PublishThread();
  PublishThread(const PublishThread&) = delete;
  PublishThread& operator=(const PublishThread&) = delete;

  // Queues `message` for `publisher`; returns at once.
  template <class Message>
  void publish(const ros::Publisher& publisher, Message message) {
    auto shared = boost::make_shared<const Message>(std::move(message));
    push([publisher, shared] { publisher.publish(shared); });
  }

  // Returns once everything queued before the call has been published.
  void flush();

  // Messages published so far (for tests and benchmarks).
  std::uint64_t published() const;

 private:
  void push(std::function<void()> job);
  void run();

  mutable std::mutex mutex_;
  std::condition_variable wake_;       // the worker: a message came while it slept, or stop
  std::condition_variable published_;  // flush(): a batch went out
  std::vector<std::function<void()>> queue_;
  std::uint64_t queued_ = 0;     // handed over so far
  std::uint64_t published_count_ = 0;
  bool sleeping_ = false;
  bool stop_ = false;
  std::thread worker_;
};

// The process's publishing thread, started on first use and stopped at exit.
PublishThread& instance();

// instance().publish(publisher, message).
template <class Message>
void publish(const ros::Publisher& publisher, Message message) {
  instance().publish(publisher, std::move(message));
}

}  // namespace publish_thread
