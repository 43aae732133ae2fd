/// \file SlicerProgress.h
/// Progress on stdout in the tag format 3D Slicer parses from an executable CLI
/// (slicer-conventions.md §2.7, after Slicer's itkPluginFilterWatcher):
///
///     <filter-start>
///     <filter-name>SegmentLumen</filter-name>
///     <filter-comment> "Segmenting the lumen" </filter-comment>
///     </filter-start>
///     <filter-progress>0.42</filter-progress>
///     <filter-end>
///     <filter-name>SegmentLumen</filter-name>
///     <filter-time>1.23</filter-time>
///     </filter-end>
///
/// One tag per line, each line flushed; `<filter-progress>` is the overall fraction in [0, 1] and
/// never decreases; no `<` appears inside a tag's content (it is replaced), so Slicer's stripping
/// regular expressions remove every tag. Each stage carries a weight; the overall fraction of a
/// report inside a stage is (weights of finished stages + fraction × stage weight) / total.
#pragma once

#include <chrono>
#include <ostream>
#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

class SlicerProgress
{
public:
  struct Stage
  {
    std::string name; ///< the <filter-name>, e.g. "SegmentLumen"
    double weight;    ///< share of the whole run, any positive unit
  };

  SlicerProgress(std::ostream& out, std::vector<Stage> stages);

  /// Opens the stage `name` (one of the stages, after the last one opened; stages skipped count
  /// as done) with a comment, closing an open stage first.
  /// \throws std::logic_error for a stage that is not declared after the last one.
  void Begin(const std::string& name, const std::string& comment);
  /// Reports `fraction` in [0, 1] of the current stage.
  void Report(double fraction);
  /// A callback for Logic functions that reports into the current stage.
  ProgressCallback Callback();
  /// The open stage's work ran elsewhere (on another core, while earlier stages ran) for `seconds`:
  /// End reports that as its time instead of the time since Begin (which is only the wait for it).
  void SetOwnTime(double seconds);
  /// Closes the current stage with its elapsed time in seconds (or the time SetOwnTime gave).
  void End();

private:
  void Emit(double overall);

  std::ostream& m_Out;
  std::vector<Stage> m_Stages;
  double m_Total = 0.0;
  double m_Done = 0.0;
  double m_LastEmitted = -1.0;
  std::size_t m_Current = 0; ///< the open (or last) stage
  std::size_t m_Next = 0;    ///< where Begin looks for the next stage
  bool m_Open = false;
  std::chrono::steady_clock::time_point m_Start;
  double m_OwnSeconds = -1.0; ///< SetOwnTime's, for the open stage; < 0: none
};

} // namespace sgp
