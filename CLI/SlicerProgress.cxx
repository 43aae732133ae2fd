#include "SlicerProgress.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace sgp
{

namespace
{

/// Tag content may not contain '<' (Slicer strips tags with `<tag>[^<]*</tag>`) nor line breaks.
std::string TagSafe(std::string text)
{
  for (char& c : text)
  {
    if (c == '<' || c == '\n' || c == '\r')
    {
      c = ' ';
    }
  }
  return text;
}

} // namespace

SlicerProgress::SlicerProgress(std::ostream& out, std::vector<Stage> stages)
  : m_Out(out)
  , m_Stages(std::move(stages))
{
  for (const Stage& stage : m_Stages)
  {
    m_Total += stage.weight;
  }
}

void SlicerProgress::Begin(const std::string& name, const std::string& comment)
{
  if (m_Open)
  {
    End();
  }
  std::size_t next = m_Next;
  while (next < m_Stages.size() && m_Stages[next].name != name)
  {
    m_Done += m_Stages[next].weight;
    ++next;
  }
  if (next >= m_Stages.size())
  {
    throw std::logic_error("SlicerProgress: stage " + name + " is not declared after the current one");
  }
  m_Current = next;
  m_Next = next + 1;
  m_Open = true;
  m_Start = std::chrono::steady_clock::now();
  m_OwnSeconds = -1.0;
  m_Out << "<filter-start>" << std::endl;
  m_Out << "<filter-name>" << TagSafe(name) << "</filter-name>" << std::endl;
  m_Out << "<filter-comment> \"" << TagSafe(comment) << "\" </filter-comment>" << std::endl;
  m_Out << "</filter-start>" << std::endl;
  Emit(m_Done / m_Total);
}

void SlicerProgress::Report(double fraction)
{
  const double f = std::clamp(fraction, 0.0, 1.0);
  Emit((m_Done + f * m_Stages[m_Current].weight) / m_Total);
}

ProgressCallback SlicerProgress::Callback()
{
  return [this](double fraction, std::string_view) { Report(fraction); };
}

void SlicerProgress::SetOwnTime(double seconds)
{
  m_OwnSeconds = std::max(0.0, seconds);
}

void SlicerProgress::End()
{
  const double seconds = m_OwnSeconds >= 0.0
                           ? m_OwnSeconds
                           : std::chrono::duration<double>(std::chrono::steady_clock::now() - m_Start).count();
  m_Done += m_Stages[m_Current].weight;
  Emit(m_Done / m_Total);
  char time[32];
  std::snprintf(time, sizeof(time), "%.3f", seconds);
  m_Out << "<filter-end>" << std::endl;
  m_Out << "<filter-name>" << TagSafe(m_Stages[m_Current].name) << "</filter-name>" << std::endl;
  m_Out << "<filter-time>" << time << "</filter-time>" << std::endl;
  m_Out << "</filter-end>" << std::endl;
  m_Open = false;
}

void SlicerProgress::Emit(double overall)
{
  const double value = std::clamp(overall, 0.0, 1.0);
  // Never decrease; skip reports that change less than 1 % unless they complete the run.
  if (value < m_LastEmitted + 0.01 && !(value >= 1.0 && m_LastEmitted < 1.0))
  {
    return;
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.4f", value);
  m_Out << "<filter-progress>" << text << "</filter-progress>" << std::endl;
  m_LastEmitted = value;
}

} // namespace sgp
