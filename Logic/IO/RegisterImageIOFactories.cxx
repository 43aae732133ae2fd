#include "IO/RegisterImageIOFactories.h"

#include <cstring>
#include <mutex>

#include <itkGDCMImageIOFactory.h>
#include <itkMetaImageIOFactory.h>
#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>
#include <itkObjectFactoryBase.h>

namespace sgp
{

namespace
{

template<typename Factory>
void RegisterUnlessRegistered()
{
  const char* name = Factory::New()->GetNameOfClass();
  for (itk::ObjectFactoryBase* registered : itk::ObjectFactoryBase::GetRegisteredFactories())
  {
    if (std::strcmp(registered->GetNameOfClass(), name) == 0)
      return;
  }
  Factory::RegisterOneFactory();
}

} // namespace

void RegisterImageIOFactories()
{
  static std::once_flag once;
  std::call_once(once,
                 []
                 {
                   RegisterUnlessRegistered<itk::NrrdImageIOFactory>();
                   RegisterUnlessRegistered<itk::NiftiImageIOFactory>();
                   RegisterUnlessRegistered<itk::MetaImageIOFactory>();
                   RegisterUnlessRegistered<itk::GDCMImageIOFactory>();
                 });
}

} // namespace sgp
