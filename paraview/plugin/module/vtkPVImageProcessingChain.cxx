#include "vtkPVImageProcessingChain.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkSmartPointer.h"

#include <vector>

class vtkPVImageProcessingChain::Internals
{
public:
  std::vector<vtkSmartPointer<vtkImageProcessingPass>> Passes;
};

vtkStandardNewMacro(vtkPVImageProcessingChain);

//------------------------------------------------------------------------------
vtkPVImageProcessingChain::vtkPVImageProcessingChain()
  : Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPVImageProcessingChain::~vtkPVImageProcessingChain() = default;

//------------------------------------------------------------------------------
void vtkPVImageProcessingChain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Passes: " << this->Impl->Passes.size() << "\n";
  for (const auto& pass : this->Impl->Passes)
  {
    os << indent.GetNextIndent() << (pass ? pass->GetClassName() : "(none)") << "\n";
  }
}

//------------------------------------------------------------------------------
void vtkPVImageProcessingChain::AddPass(vtkImageProcessingPass* pass)
{
  this->Impl->Passes.emplace_back(pass);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVImageProcessingChain::RemoveAllPasses()
{
  if (!this->Impl->Passes.empty())
  {
    // Unlink, so a removed pass does not keep the scene (or another pass) alive.
    for (const auto& pass : this->Impl->Passes)
    {
      if (pass)
      {
        pass->SetDelegatePass(nullptr);
      }
    }
    this->Impl->Passes.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkPVImageProcessingChain::GetNumberOfPasses()
{
  return static_cast<int>(this->Impl->Passes.size());
}

//------------------------------------------------------------------------------
vtkImageProcessingPass* vtkPVImageProcessingChain::GetPass(int index)
{
  if (index < 0 || index >= this->GetNumberOfPasses())
  {
    return nullptr;
  }
  return this->Impl->Passes[index];
}

//------------------------------------------------------------------------------
void vtkPVImageProcessingChain::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderPass* last = this->DelegatePass;
  for (const auto& pass : this->Impl->Passes)
  {
    if (pass)
    {
      pass->SetDelegatePass(last);
      last = pass;
    }
  }
  if (last)
  {
    last->Render(s);
    this->NumberOfRenderedProps = last->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
void vtkPVImageProcessingChain::ReleaseGraphicsResources(vtkWindow* w)
{
  for (const auto& pass : this->Impl->Passes)
  {
    if (pass)
    {
      pass->ReleaseGraphicsResources(w);
    }
  }
  this->Superclass::ReleaseGraphicsResources(w);
}
