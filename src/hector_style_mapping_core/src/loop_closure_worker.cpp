#include "hector_style_mapping_core/loop_closure_worker.h"

#include <utility>

namespace hector_style_mapping {

LoopClosureWorker::LoopClosureWorker(const MapperOptions& map_options, LoopClosureThreading threading)
    : map_options_(map_options), threading_(threading) {
  if (threading_ == LoopClosureThreading::kBackground) thread_ = std::thread([this] { run(); });
}

LoopClosureWorker::~LoopClosureWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void LoopClosureWorker::submit(const ScanPoints& scan, const Pose2D& step) {
  if (threading_ == LoopClosureThreading::kInline) {
    process({scan, step});
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back({scan, step});
  }
  changed_.notify_all();
}

std::optional<LoopClosureUpdate> LoopClosureWorker::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<LoopClosureUpdate> update = std::move(update_);
  update_.reset();
  return update;
}

void LoopClosureWorker::waitUntilIdle() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return (queue_.empty() && !busy_) || stopping_; });
}

LoopClosureStats LoopClosureWorker::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void LoopClosureWorker::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
    if (stopping_) return;
    Keyframe keyframe = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    process(keyframe);
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

void LoopClosureWorker::process(const Keyframe& keyframe) {
  const int previous = loop_closure_.keyframes() - 1;
  const Pose2D matched = previous < 0 ? keyframe.step : compose(loop_closure_.pose(previous), keyframe.step);
  const bool closed = loop_closure_.addKeyframe(keyframe.scan, matched);

  std::optional<LoopClosureUpdate> update;
  if (closed) {
    update.emplace();
    for (int i = 0; i < loop_closure_.keyframes(); ++i) update->poses.push_back(loop_closure_.pose(i));
    // The redraw, the costly part of adopting a closure (0.1-0.2 s for a building), is done here: in the
    // background off the scan path; inline too, so that the scans after a closure are matched against the
    // same redrawn map either way (live and offline the same mapper).
    update->map = std::make_shared<MultiResolutionMap>(map_options_);
    for (int i = 0; i < loop_closure_.keyframes(); ++i)
      update->map->updateByScan(loop_closure_.scan(i), loop_closure_.pose(i));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (update) update_ = std::move(update);
  stats_.keyframes = loop_closure_.keyframes();
  stats_.attempts = loop_closure_.attempts();
  stats_.inconsistent = loop_closure_.inconsistent();
  stats_.ambiguous = loop_closure_.ambiguous();
  stats_.closures = loop_closure_.acceptedClosures();
}

}  // namespace hector_style_mapping
