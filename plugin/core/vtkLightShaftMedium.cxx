#include "vtkLightShaftMedium.h"
#include "vtkLightShaftMediumInternals.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftSetters.h"
#include "vtkLightShaftVolumeField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <limits>

namespace
{
constexpr double MaximumCoefficient = 1.0e6;
constexpr double MaximumAnisotropy = 0.99;
using vtkLightShaftSetters::SetClamped;
}

vtkStandardNewMacro(vtkLightShaftMedium);

vtkLightShaftMedium::vtkLightShaftMedium()
  : Impl(new Internals)
{
}

vtkLightShaftMedium::~vtkLightShaftMedium() = default;

//------------------------------------------------------------------------------
void vtkLightShaftMedium::SetScatteringCoefficient(double r, double g, double b)
{
  this->Impl->CoefficientsSet.Modified();
  SetClamped(this,
    "ScatteringCoefficient",
    this->ScatteringCoefficient,
    { r, g, b },
    0.0,
    MaximumCoefficient);
}

void vtkLightShaftMedium::SetScatteringCoefficient(const double rgb[3])
{
  this->SetScatteringCoefficient(rgb[0], rgb[1], rgb[2]);
}

void vtkLightShaftMedium::SetScatteringCoefficient(double grey)
{
  this->SetScatteringCoefficient(grey, grey, grey);
}

void vtkLightShaftMedium::SetAbsorptionCoefficient(double r, double g, double b)
{
  this->Impl->CoefficientsSet.Modified();
  SetClamped(this,
    "AbsorptionCoefficient",
    this->AbsorptionCoefficient,
    { r, g, b },
    0.0,
    MaximumCoefficient);
}

void vtkLightShaftMedium::SetAbsorptionCoefficient(const double rgb[3])
{
  this->SetAbsorptionCoefficient(rgb[0], rgb[1], rgb[2]);
}

void vtkLightShaftMedium::SetAbsorptionCoefficient(double grey)
{
  this->SetAbsorptionCoefficient(grey, grey, grey);
}

vtkMTimeType vtkLightShaftMedium::GetCoefficientsSetTime()
{
  return this->Impl->CoefficientsSet.GetMTime();
}

void vtkLightShaftMedium::SetAnisotropy(double g)
{
  SetClamped(this, "Anisotropy", &this->Anisotropy, { g }, -MaximumAnisotropy, MaximumAnisotropy);
}

void vtkLightShaftMedium::SetNoiseAmplitude(double amplitude)
{
  SetClamped(this, "NoiseAmplitude", &this->NoiseAmplitude, { amplitude }, 0.0, 1.0);
}

void vtkLightShaftMedium::SetNoiseScale(double scale)
{
  SetClamped(this, "NoiseScale", &this->NoiseScale, { scale }, 0.01, 1000.0);
}

void vtkLightShaftMedium::SetNoiseVelocity1(double u, double v)
{
  SetClamped(this, "NoiseVelocity1", this->NoiseVelocity1, { u, v }, -1e3, 1e3);
}

void vtkLightShaftMedium::SetNoiseVelocity2(double u, double v)
{
  SetClamped(this, "NoiseVelocity2", this->NoiseVelocity2, { u, v }, -1e3, 1e3);
}

void vtkLightShaftMedium::SetNoiseTexture(vtkTexture* noise)
{
  if (this->Impl->NoiseTexture != noise)
  {
    this->Impl->NoiseTexture = noise;
    this->Modified();
  }
}

vtkTexture* vtkLightShaftMedium::GetNoiseTexture()
{
  return this->Impl->NoiseTexture;
}

void vtkLightShaftMedium::SetTime(double time)
{
  SetClamped(this,
    "Time",
    &this->Time,
    { time },
    -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max());
}

void vtkLightShaftMedium::SetDensityScale(double scale)
{
  SetClamped(this, "DensityScale", &this->DensityScale, { scale }, 0.0, MaximumCoefficient);
}

void vtkLightShaftMedium::SetBackgroundDensity(double density)
{
  SetClamped(
    this, "BackgroundDensity", &this->BackgroundDensity, { density }, 0.0, MaximumCoefficient);
}

//------------------------------------------------------------------------------
// The density field: an image checked when set, or a pipeline's output checked at each render.
void vtkLightShaftMedium::SetDensityField(vtkImageData* density)
{
  Internals& impl = *this->Impl;
  vtkLightShaftDensityField field;
  const std::string why = density ? field.Read(density, impl.ArrayName.c_str()) : "";
  if (!why.empty())
  {
    vtkErrorMacro("DensityField: the image " << why << "; the previous density field is kept.");
    return;
  }
  impl.Keep(density, impl.ArrayName, std::move(field));
  if (impl.Density != density || impl.Producer || impl.Volume)
  {
    impl.Volume = nullptr;
    impl.VolumeDensity = nullptr;
    impl.Density = density;
    impl.Producer = nullptr;
    impl.Output = nullptr;
    this->Modified();
  }
}

vtkImageData* vtkLightShaftMedium::GetDensityField()
{
  const Internals& impl = *this->Impl;
  return impl.Volume ? impl.VolumeDensity.Get()
                     : (impl.Producer ? impl.Output.Get() : impl.Density.Get());
}

void vtkLightShaftMedium::SetDensityFieldConnection(vtkAlgorithmOutput* output)
{
  Internals& impl = *this->Impl;
  vtkAlgorithm* producer = output ? output->GetProducer() : nullptr;
  const int port = output ? output->GetIndex() : 0;
  if (producer == impl.Producer && port == impl.Port && (producer || !impl.Density) && !impl.Volume)
  {
    return;
  }
  impl.Producer = producer;
  impl.Port = port;
  if (!producer)
  {
    impl.Output = nullptr; // (else kept until the new output is an image)
  }
  impl.OutputError.clear();
  impl.Density = nullptr;
  impl.Volume = nullptr;
  impl.VolumeDensity = nullptr;
  this->Modified();
}

void vtkLightShaftMedium::SetDensityVolume(vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  if (volume == impl.Volume && (volume || (!impl.Density && !impl.Producer)))
  {
    return;
  }
  impl.Volume = volume;
  impl.VolumeDensity = nullptr;
  impl.VolumeTime = 0;
  impl.VolumeError.clear();
  impl.Density = nullptr;
  impl.Producer = nullptr;
  impl.Output = nullptr;
  this->Modified();
}

vtkVolume* vtkLightShaftMedium::GetDensityVolume()
{
  return this->Impl->Volume;
}

vtkAlgorithmOutput* vtkLightShaftMedium::GetDensityFieldConnection()
{
  vtkAlgorithm* producer = this->Impl->Producer;
  return producer ? producer->GetOutputPort(this->Impl->Port) : nullptr;
}

void vtkLightShaftMedium::SetDensityArrayName(const char* name)
{
  Internals& impl = *this->Impl;
  const std::string wanted = name ? name : "";
  vtkLightShaftDensityField field;
  vtkImageData* density = impl.Density; // (a pipeline's output: checked at each render)
  const std::string why = density ? field.Read(density, wanted.c_str()) : "";
  if (!why.empty())
  {
    vtkErrorMacro("DensityArrayName: the density image " << why << "; the previous name is kept.");
    return;
  }
  if (density)
  {
    impl.Keep(density, wanted, std::move(field));
  }
  if (impl.ArrayName != wanted)
  {
    impl.ArrayName = wanted;
    this->Modified();
  }
}

const char* vtkLightShaftMedium::GetDensityArrayName()
{
  return this->Impl->ArrayName.c_str();
}

vtkImageData* vtkLightShaftMedium::UpdateDensityField(vtkObject* caller)
{
  Internals& impl = *this->Impl;
  if (impl.Volume)
  {
    return impl.UpdateVolumeDensity(caller);
  }
  if (!impl.Producer)
  {
    return impl.Density;
  }
  impl.Producer->Update(impl.Port);
  vtkDataObject* output = impl.Producer->GetOutputDataObject(impl.Port);
  if (vtkImageData* image = vtkImageData::SafeDownCast(output))
  {
    impl.Output = image;
    impl.OutputError.clear();
    return image;
  }
  const std::string why = std::string("the pipeline's output is ") +
                          (output ? output->GetClassName() : "missing") + ", not a vtkImageData";
  if (why != impl.OutputError)
  {
    vtkErrorWithObjectMacro(
      caller, "DensityFieldConnection: " << why << "; the last usable density field is kept.");
    impl.OutputError = why;
  }
  return impl.Output;
}

//------------------------------------------------------------------------------
void vtkLightShaftMedium::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto print = [&os, indent](const char* name, const double* v, int n)
  {
    os << indent << name << ": (";
    for (int i = 0; i < n; ++i)
    {
      os << (i ? ", " : "") << v[i];
    }
    os << ")\n";
  };
  print("ScatteringCoefficient", this->ScatteringCoefficient, 3);
  print("AbsorptionCoefficient", this->AbsorptionCoefficient, 3);
  os << indent << "PhaseFunction: " << this->PhaseFunction << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "NoiseAmplitude: " << this->NoiseAmplitude << "\n";
  os << indent << "NoiseScale: " << this->NoiseScale << "\n";
  print("NoiseVelocity1", this->NoiseVelocity1, 2);
  print("NoiseVelocity2", this->NoiseVelocity2, 2);
  os << indent << "NoiseTexture: " << this->Impl->NoiseTexture.Get() << "\n";
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "DensityField: " << this->Impl->Density.Get() << " (connection "
     << this->Impl->Producer.Get() << ", array \"" << this->Impl->ArrayName << "\")\n";
  os << indent << "DensityVolume: " << this->Impl->Volume.Get() << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "BackgroundDensity: " << this->BackgroundDensity << "\n";
  os << indent << "FieldShadowResolution: " << this->FieldShadowResolution << "\n";
  os << indent << "FieldResolution: " << this->FieldResolution << "\n";
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightShaftMedium::Internals::UpdateVolumeDensity(vtkObject* caller)
{
  if (vtkAbstractMapper* mapper = this->Volume->GetMapper())
  {
    mapper->Update(); // (its input brought up to date, as its render would)
  }
  const vtkMTimeType time = vtkLightShaftVolumeField::Time(this->Volume);
  if (this->VolumeDensity && time <= this->VolumeTime && this->ArrayName == this->VolumeArrayName)
  {
    return this->VolumeDensity;
  }
  vtkNew<vtkImageData> image;
  const std::string why = vtkLightShaftVolumeField::Build(
    this->Volume, vtkLightShaftVolumeField::Quantity::Opacity, image);
  if (!why.empty())
  {
    if (why != this->VolumeError)
    {
      vtkErrorWithObjectMacro(
        caller, "DensityVolume: the volume " << why << "; the last usable density field is kept.");
      this->VolumeError = why;
    }
    return this->VolumeDensity;
  }
  // (Named as the medium's array, so that the field is read from it whatever that is.)
  vtkDataArray* values = image->GetPointData()->GetScalars() ? image->GetPointData()->GetScalars()
                                                             : image->GetCellData()->GetScalars();
  values->SetName(this->ArrayName.empty() ? "Opacity" : this->ArrayName.c_str());
  this->VolumeError.clear();
  this->VolumeDensity = image;
  this->VolumeTime = time;
  this->VolumeArrayName = this->ArrayName;
  return this->VolumeDensity;
}
