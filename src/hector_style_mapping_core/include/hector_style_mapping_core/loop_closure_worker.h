#ifndef HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_WORKER_H
#define HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_WORKER_H

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "hector_style_mapping_core/loop_closure.h"
#include "hector_style_mapping_core/mapper_options.h"
#include "hector_style_mapping_core/multi_resolution_map.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// Where LoopClosure's work is done: in the caller's thread, as it hands each keyframe over (kInline: the same
// result every run, for benchmarks and tests), or in a thread of its own (kBackground: a live node's scan path
// never waits for a closure's searches, the graph optimisation or the map's redraw).
enum class LoopClosureThreading { kInline, kBackground };

// What loop closure has done so far, for diagnostics.
struct LoopClosureStats {
  int keyframes = 0;
  int attempts = 0;
  int inconsistent = 0;
  int ambiguous = 0;
  std::vector<LoopClosure::Closure> closures;
};

// A closed loop, for the front end to adopt: the optimised poses of keyframes 0 .. poses.size() - 1 and the map
// redrawn from them.
struct LoopClosureUpdate {
  std::vector<Pose2D> poses;
  std::shared_ptr<MultiResolutionMap> map;
};

// Runs a LoopClosure on the keyframes it is given, in order. Each keyframe comes with the front end's step
// from the keyframe before (in the front end's frame at the time), not its map pose: the front end moves its
// frame when it adopts an update, and a step stays true across that. Thread-safe: one front-end thread
// submits and takes; the worker thread (kBackground) owns the LoopClosure.
class LoopClosureWorker {
 public:
  LoopClosureWorker(const MapperOptions& map_options, LoopClosureThreading threading);
  ~LoopClosureWorker();  // the keyframes not yet processed are dropped
  LoopClosureWorker(const LoopClosureWorker&) = delete;
  LoopClosureWorker& operator=(const LoopClosureWorker&) = delete;

  // Keyframe `scan`, `step` (the first: its pose) after the keyframe before. Inline, processed before it returns.
  void submit(const ScanPoints& scan, const Pose2D& step);
  // The newest closed loop not yet taken (an older one is contained in it), if any.
  std::optional<LoopClosureUpdate> take();
  // Returns once every keyframe submitted has been processed.
  void waitUntilIdle();
  LoopClosureStats stats() const;

 private:
  struct Keyframe {
    ScanPoints scan;
    Pose2D step;
  };
  void process(const Keyframe& keyframe);  // worker thread (kBackground) or caller (kInline)
  void run();

  const MapperOptions map_options_;
  const LoopClosureThreading threading_;
  LoopClosure loop_closure_;  // touched by process() only

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable changed_;
  std::deque<Keyframe> queue_;
  bool busy_ = false;
  bool stopping_ = false;
  std::optional<LoopClosureUpdate> update_;
  LoopClosureStats stats_;
  std::thread thread_;  // last: started once the rest is built
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_WORKER_H
