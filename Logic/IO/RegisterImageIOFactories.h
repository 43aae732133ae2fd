/// \file RegisterImageIOFactories.h
/// Registers the ITK ImageIO factories of the formats the readers and writers of this folder
/// handle: NRRD, NIfTI, MetaImage and GDCM (DICOM).
///
/// In the standalone build ITK's UseITK already registers them (its generated register manager,
/// ITK_IO_FACTORY_REGISTER_MANAGER). Inside Slicer it does not: Slicer sets
/// ITK_NO_IO_FACTORY_REGISTER_MANAGER (ITK_NO_IMAGEIO_FACTORY_REGISTER_MANAGER from ITK 5.3) and
/// registers the factories in its own CLI launcher, which a test program or any other binary built
/// with this library does not have; without them no file could be read or written. So every binary
/// that links sgpIO calls this at start-up (Logic/IO/CMakeLists.txt compiles
/// ImageIOFactoryRegistrar.cxx into each), and the reader calls it again before reading.
///
/// It may be called any number of times, from any thread: a factory whose class is already
/// registered (by UseITK's manager, by Slicer or by an earlier call) is not registered again.
#pragma once

namespace sgp
{

void RegisterImageIOFactories();

} // namespace sgp
