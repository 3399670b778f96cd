/**
 * @class   vtkPVImageProcessingChain
 * @brief   Runs image-processing passes one after another in the one image-processing slot of
 *          ParaView's synchronized renderers.
 *
 * vtkPVSynchronizedRenderer (ParaView 5.11) has a single image-processing slot: the pass put
 * there gets the scene (the camera pass, or the IceT compositing pass in parallel) as its
 * delegate, and the render view puts its tone-mapping pass there when tone mapping is on. Put
 * a chain there instead, and every pass of the chain runs: the first renders the chain's
 * delegate (the scene), each next one processes the image of the one before it, and the last
 * one's output is the frame. Passes are linked (their delegates set) at every Render(), so
 * the slot's owner may change the chain's delegate at any time.
 *
 * The view vtkPVLightShaftsView uses it to run vtkLightShaftPass and then tone mapping.
 *
 * @sa vtkPVLightShaftsView vtkImageProcessingPass
 */

#ifndef vtkPVImageProcessingChain_h
#define vtkPVImageProcessingChain_h

#include "vtkImageProcessingPass.h" // For the base class
#include "vtkPVLightShaftsModule.h" // For the export macro

#include <memory> // For std::unique_ptr (the pass list lives in Internals)

class VTKLIGHTSHAFTS_EXPORT vtkPVImageProcessingChain : public vtkImageProcessingPass
{
public:
  static vtkPVImageProcessingChain* New();
  vtkTypeMacro(vtkPVImageProcessingChain, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Link the passes (first: the chain's delegate; each next: the one before) and render the
   * last. With no passes, renders the delegate.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Release the GL resources of every pass of the chain and of the delegate.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The passes, in the order they process the image. Null passes are skipped. Adding or
   * removing a pass modifies the chain.
   */
  void AddPass(vtkImageProcessingPass* pass);
  void RemoveAllPasses();
  int GetNumberOfPasses();
  vtkImageProcessingPass* GetPass(int index);
  ///@}

protected:
  vtkPVImageProcessingChain();
  ~vtkPVImageProcessingChain() override;

private:
  vtkPVImageProcessingChain(const vtkPVImageProcessingChain&) = delete;
  void operator=(const vtkPVImageProcessingChain&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
