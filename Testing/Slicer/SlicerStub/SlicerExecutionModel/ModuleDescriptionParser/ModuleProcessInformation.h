// Stand-in for SEM's ModuleDescriptionParser/ModuleProcessInformation.h, which SEM's generated
// <Name>CLP.h includes: the structure Slicer fills in for a shared-library CLI (progress, abort,
// elapsed time). Written for the stub from SEM's header's documented fields; none of its code.
#pragma once

extern "C"
{
  struct ModuleProcessInformation
  {
    unsigned char Abort;
    float Progress;
    float StageProgress;
    char ProgressMessage[1024];
    void (*ProgressCallbackFunction)(void*);
    void* ProgressCallbackClientData;
    double ElapsedTime;
  };
}
