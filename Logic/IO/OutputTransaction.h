/// \file OutputTransaction.h
/// All-or-nothing output files: a run leaves either every requested output or none.
///
/// Each output is first written to a staged path beside its final one (same folder, so the final
/// rename cannot cross file systems; same extension, so ITK and VTK pick the same format), e.g.
/// `lumen.nrrd` → `lumen.sgp-partial-qxkzmv.nrrd`. Commit() renames them all; the destructor
/// removes every staged file that was not committed, so an exception thrown between Stage() and
/// Commit() leaves nothing behind. A rename failure during Commit() removes the outputs already
/// renamed in that commit and throws InputError naming the path.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sgp
{

class OutputTransaction
{
public:
  OutputTransaction() = default;
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  ~OutputTransaction();

  /// The path to write `finalPath`'s content to.
  std::string Stage(const std::string& finalPath);

  /// Moves every staged file to its final path. \throws InputError on a failed rename.
  void Commit();

private:
  std::vector<std::pair<std::string, std::string>> m_Staged; ///< (staged, final)
};

} // namespace sgp
