#ifndef HECTOR_STYLE_MAPPING_CORE_CORRELATIVE_SEARCH_H
#define HECTOR_STYLE_MAPPING_CORE_CORRELATIVE_SEARCH_H

#include "hector_style_mapping_core/likelihood_field.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// Half-widths of the region searched round a predicted pose.
struct SearchWindow {
  double linear = 0.0;   // m, along x and along y
  double angular = 0.0;  // rad
};

// A preference for translations near an expected position, where the scan cannot tell places apart (along a
// featureless corridor every position fits about as well): a candidate's score pays `weight` per metre it lies
// from `expected` (map frame). Weight 0: no preference.
struct TranslationPrior {
  Eigen::Vector2d expected{0.0, 0.0};
  double weight = 0.0;  // mean field value per metre
};

struct SearchResult {
  Pose2D pose;          // the best pose found (the centre when nothing scores)
  double score = 0.0;   // its mean field value per scan point, -1..1 (LikelihoodField)
  long candidates = 0;  // poses scored, blocks of the branch and bound included
  double angle_step = 0.0;  // rad between the rotations searched
};

// Correlative search (Olson, "Real-time correlative scan matching", ICRA 2009): the pose within `window` of
// `centre` whose scan points have the highest mean value in `field`. Rotations are stepped so that the farthest
// points (the 95th percentile of ranges) move by LikelihoodField::kSigma; at each, translations one cell apart
// are searched exactly by branch and bound over the field's blocks (as Cartographer's fast correlative matcher
// does), so a window of metres costs a fraction of the brute-force search. The winner is then refined by brute
// force over a finer grid (a fifth of a cell, a quarter of a rotation step) on the interpolated field.
// With a prior, the grid's winner is the best score less the prior's cost (the refinement does not pay it: it
// moves by less than a cell). Ties go to the candidate nearest the centre. The scan's free_rays are not read.
SearchResult correlativeSearch(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& centre,
                               const SearchWindow& window, const TranslationPrior& prior = TranslationPrior{});

// The field's levels a search over `window` reads (LikelihoodField::ensureLevels): its branch and bound starts
// from the finest blocks as wide as the window.
int searchLevels(const SearchWindow& window);

// The best fit elsewhere: correlativeSearch (no prior) over the poses whose translation lies more than
// `excluded_radius` (m, along x or along y) from `excluded`. Score -inf when the window holds none. A second fit
// nearly as good as the first says the scan cannot tell the two places apart (a corridor, a row of look-alike
// rooms).
SearchResult correlativeSearchElsewhere(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& centre,
                                        const SearchWindow& window, const Eigen::Vector2d& excluded,
                                        double excluded_radius);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_CORRELATIVE_SEARCH_H
