#include "publish_thread/publish_thread.h"

#include <ros/init.h>

#include <chrono>

namespace publish_thread {
namespace {

// realtime_tools' RealtimePublisher polls at this period.
constexpr std::chrono::microseconds kPollPeriod(500);
// Empty polls before the worker sleeps until woken: 10 ms without a message.
constexpr int kIdlePollsBeforeSleep = 20;

}  // namespace

PublishThread::PublishThread() : worker_([this] { run(); }) {}

PublishThread::~PublishThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  worker_.join();
}

void PublishThread::push(std::function<void()> job) {
  bool wake;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(job));
    ++queued_;
    wake = sleeping_;
  }
  if (wake) wake_.notify_one();
}

void PublishThread::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t target = queued_;
  if (sleeping_) wake_.notify_one();
  published_.wait(lock, [&] { return published_count_ >= target || stop_; });
}

std::uint64_t PublishThread::published() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return published_count_;
}

void PublishThread::run() {
  std::vector<std::function<void()>> batch;
  int idle_polls = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (queue_.empty()) {
      if (stop_) break;
      if (idle_polls >= kIdlePollsBeforeSleep) {
        sleeping_ = true;
        wake_.wait(lock, [&] { return stop_ || !queue_.empty(); });
        sleeping_ = false;
        idle_polls = 0;
      } else {
        lock.unlock();
        std::this_thread::sleep_for(kPollPeriod);
        lock.lock();
        ++idle_polls;
      }
      continue;
    }
    batch.swap(queue_);
    lock.unlock();
    // After ros::shutdown() the publishers are gone: what is left can go nowhere.
    const bool up = ros::ok();
    for (auto& job : batch) {
      if (up) job();
    }
    const std::size_t count = batch.size();
    batch.clear();  // the messages and publisher handles go here, outside the lock
    lock.lock();
    published_count_ += count;
    idle_polls = 0;
    published_.notify_all();
  }
}

PublishThread& instance() {
  // Constructed on first use, after roscpp's own singletons, so destroyed before them at exit.
  static PublishThread thread;
  return thread;
}

}  // namespace publish_thread
