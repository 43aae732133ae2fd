// The Slicer stub's CLI launcher (SlicerExecutionModel_CLI_LIBRARY_WRAPPER_CXX): the executable
// SEMMacroBuildCLI links with <Name>Lib. Like SEM's CMake/SEMCommandLineLibraryWrapper.cxx it only
// calls the module's entry point. Slicer's own wrapper (Base/CLI/SEMCommandLineLibraryWrapper.cxx.in)
// first calls itk::itkFactoryRegistration(); this one deliberately does not, so a module built
// against the stub must register the ITK ImageIO factories it needs itself.
#if defined(_WIN32) && !defined(MODULE_STATIC)
#define MODULE_IMPORT __declspec(dllimport)
#else
#define MODULE_IMPORT
#endif

extern "C" MODULE_IMPORT int ModuleEntryPoint(int, char*[]);

int main(int argc, char** argv)
{
  return ModuleEntryPoint(argc, argv);
}
