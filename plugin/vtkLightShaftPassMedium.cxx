// A medium from data: vtkLightShaftPass's density field, given as an image or by a pipeline (its
// other parameters and the frame's recipe are in vtkLightShaftPass.cxx).
#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"

#include "vtkAlgorithmOutput.h"
#include "vtkDataObject.h"
#include "vtkLightShaftDensityField.h"

void vtkLightShaftPass::SetMediumDensity(vtkImageData* density)
{
  vtkLightShaftDensityField field;
  const std::string why =
    density ? field.Read(density, this->Impl->MediumDensityArrayName.c_str()) : "";
  if (!why.empty())
  {
    vtkErrorMacro("MediumDensity: the image " << why << "; the previous density field is kept.");
    return;
  }
  this->Impl->Medium.Adopt(density, this->Impl->MediumDensityArrayName, std::move(field));
  if (this->Impl->MediumDensity != density || this->Impl->MediumProducer)
  {
    this->Impl->MediumDensity = density;
    this->Impl->MediumProducer = nullptr;
    this->Impl->MediumOutput = nullptr;
    this->Modified();
  }
}

vtkImageData* vtkLightShaftPass::GetMediumDensity()
{
  return this->Impl->MediumProducer ? this->Impl->MediumOutput.Get()
                                    : this->Impl->MediumDensity.Get();
}

void vtkLightShaftPass::SetMediumDensityConnection(vtkAlgorithmOutput* output)
{
  vtkAlgorithm* producer = output ? output->GetProducer() : nullptr;
  const int port = output ? output->GetIndex() : 0;
  if (producer == this->Impl->MediumProducer && port == this->Impl->MediumPort &&
      (producer || !this->Impl->MediumDensity))
  {
    return;
  }
  this->Impl->MediumProducer = producer;
  this->Impl->MediumPort = port;
  if (!producer)
  {
    this->Impl->MediumOutput = nullptr; // (else kept until the new output is an image)
  }
  this->Impl->MediumOutputError.clear();
  this->Impl->MediumDensity = nullptr;
  this->Modified();
}

vtkAlgorithmOutput* vtkLightShaftPass::GetMediumDensityConnection()
{
  vtkAlgorithm* producer = this->Impl->MediumProducer;
  return producer ? producer->GetOutputPort(this->Impl->MediumPort) : nullptr;
}

void vtkLightShaftPass::SetMediumDensityArrayName(const char* name)
{
  const std::string wanted = name ? name : "";
  vtkLightShaftDensityField field;
  vtkImageData* density = this->Impl->MediumDensity; // (a pipeline's output: checked per frame)
  const std::string why = density ? field.Read(density, wanted.c_str()) : "";
  if (!why.empty())
  {
    vtkErrorMacro(
      "MediumDensityArrayName: the density image " << why << "; the previous name is kept.");
    return;
  }
  if (density)
  {
    this->Impl->Medium.Adopt(density, wanted, std::move(field));
  }
  if (this->Impl->MediumDensityArrayName != wanted)
  {
    this->Impl->MediumDensityArrayName = wanted;
    this->Modified();
  }
}

const char* vtkLightShaftPass::GetMediumDensityArrayName()
{
  return this->Impl->MediumDensityArrayName.c_str();
}

//------------------------------------------------------------------------------
// The frame's density image: SetMediumDensity's, or the pipeline's output brought up to date
// (its MTime then decides whether the texture is uploaded again). An output that is not an
// image gets one error, and the last one that was stays in use.
vtkImageData* vtkLightShaftPass::Internals::MediumImage(vtkObject* owner)
{
  if (!this->MediumProducer)
  {
    return this->MediumDensity;
  }
  this->MediumProducer->Update(this->MediumPort);
  vtkDataObject* output = this->MediumProducer->GetOutputDataObject(this->MediumPort);
  if (vtkImageData* image = vtkImageData::SafeDownCast(output))
  {
    this->MediumOutput = image;
    this->MediumOutputError.clear();
    return image;
  }
  const std::string why = std::string("the pipeline's output is ") +
                          (output ? output->GetClassName() : "missing") + ", not a vtkImageData";
  if (why != this->MediumOutputError)
  {
    vtkErrorWithObjectMacro(
      owner, "MediumDensityConnection: " << why << "; the last usable density field is kept.");
    this->MediumOutputError = why;
  }
  return this->MediumOutput;
}
