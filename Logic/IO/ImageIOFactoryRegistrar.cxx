// Compiled into every binary that links sgpIO (an INTERFACE source of sgpIO, Logic/IO/CMakeLists.txt),
// the way ITK's UseITK compiles its register manager into each program: registers the ImageIO
// factories when the program (or a CLI's shared module library) is loaded, before main(). See
// RegisterImageIOFactories.h for why Slicer builds need it.
#include "IO/RegisterImageIOFactories.h"

namespace
{

struct ImageIOFactoryRegistrar
{
  ImageIOFactoryRegistrar() { sgp::RegisterImageIOFactories(); }
};

[[maybe_unused]] const ImageIOFactoryRegistrar imageIOFactoryRegistrar;

} // namespace
