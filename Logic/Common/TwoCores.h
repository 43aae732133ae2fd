/// \file TwoCores.h
/// A loop over slices split between the calling thread and one other (the machines this tool runs
/// on have two cores or more; DESIGN.md). `body(first, end)` handles slices [first, end) of
/// `count`; the halves run at once, so it must write only what belongs to its own slices — the
/// results are then the same as one loop's, bit for bit. `split` (default: half) is where the
/// second half begins, for loops whose slices share an output cell with their neighbours (give a
/// boundary between cells). An exception from either half is rethrown once both have finished.
/// Where no thread can be started, both halves run on the calling thread.
#pragma once

#include <future>
#include <system_error>

namespace sgp
{

template<typename Body>
void OnTwoCores(long count, Body body, long split = -1)
{
  const long half = split < 0 ? count / 2 : split;
  if (count < 2 || half <= 0 || half >= count)
  {
    body(0L, count);
    return;
  }
  std::future<void> first;
  try
  {
    first = std::async(std::launch::async, [&body, half] { body(0L, half); });
  }
  catch (const std::system_error&)
  {
    body(0L, half); // no thread to spare: both halves here, one after the other
    body(half, count);
    return;
  }
  body(half, count); // should it throw, `first` is waited for as it goes out of scope
  first.get();
}

} // namespace sgp
