/// \file QuietStderr.h
/// Runs a call with the process's standard error (file descriptor 2) sent to a scratch file and
/// dropped afterwards. ITK's bundled readers print their own diagnostics straight to it — NIfTI's
/// "** ERROR: nifti_convert_nhdr2nim: bad datatype", MetaIO's "MetaImage: Read: Cannot parse
/// file", vnl's SVD warnings on a mutated direction — which would stand beside the CLI's one
/// `ERROR:` line (the reader fuzz test found them). The failure itself reaches the CLI as our
/// InputError, naming the file. When the descriptor cannot be redirected the call runs as is.
/// Not thread-safe (the descriptor is the process's): call it while nothing else writes to stderr.
#pragma once

#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace sgp::clp
{

template<typename Call>
auto WithStderrDropped(Call call) -> decltype(call())
{
  std::cerr.flush();
  std::fflush(stderr);
  const int saved = ::dup(2);
  std::FILE* sink = saved >= 0 ? std::tmpfile() : nullptr;
  if (!sink || ::dup2(::fileno(sink), 2) < 0)
  {
    if (sink)
      std::fclose(sink);
    if (saved >= 0)
      ::close(saved);
    return call();
  }
  struct Restore
  {
    int saved;
    std::FILE* sink;
    ~Restore()
    {
      std::cerr.flush();
      std::fflush(stderr);
      ::dup2(saved, 2);
      ::close(saved);
      std::fclose(sink);
    }
  } restore{ saved, sink };
  return call();
}

} // namespace sgp::clp
