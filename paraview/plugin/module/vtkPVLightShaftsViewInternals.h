/**
 * @file   vtkPVLightShaftsViewInternals.h
 * @brief  vtkPVLightShaftsView's state besides its properties: the pass, the chain it sits
 *         in, the distributed exchanges, and the settings as given (private to the module).
 */

#ifndef vtkPVLightShaftsViewInternals_h
#define vtkPVLightShaftsViewInternals_h

#include "vtkAlgorithmOutput.h"                // For the medium's connection, held
#include "vtkImageProcessingPass.h"            // For the tone-mapping pass, held
#include "vtkLight.h"                          // For the lights (weak pointers)
#include "vtkLightShaftMedium.h"               // For GiveMedium
#include "vtkLightShaftPass.h"                 // For the pass, held
#include "vtkNew.h"                            // For the objects held
#include "vtkPVImageProcessingChain.h"         // For the chain, held
#include "vtkPVLightShaftsExchange.h"          // For the exchanges, held
#include "vtkPVLightShaftsFieldGather.h"       // For the medium's gather, held
#include "vtkPVLightShaftsTranslucentGather.h" // For the surfaces' gather, held
#include "vtkPVLightShaftsView.h"              // For the class these are the internals of
#include "vtkPVLightShaftsVolumeGather.h"      // For the volume's gather, held
#include "vtkSmartPointer.h"                   // For the objects shared
#include "vtkWeakPointer.h"                    // For the lights

#include <algorithm> // For std::equal, std::copy
#include <string>    // For the cookie's file name
#include <vector>    // For the lights

class vtkPVLightShaftsView::Internals
{
public:
  vtkNew<vtkLightShaftPass> Shafts;
  vtkNew<vtkPVImageProcessingChain> Chain;
  // Under MPI: the MediumDensity source's pieces gathered into its whole image.
  vtkNew<vtkPVLightShaftsFieldGather> FieldGather;
  // Under MPI: the shadow maps, the composited depth and the in-scatter's pieces.
  vtkPVLightShaftsExchange Exchange;
  // Under MPI: the volume's pieces gathered into the whole image the pass models.
  vtkPVLightShaftsVolumeGather VolumeGather;
  // Under MPI: the translucent surfaces' pieces gathered into the whole surfaces the pass peels.
  vtkPVLightShaftsTranslucentGather TranslucentGather;
  // The render view's own tone-mapping pass (private to vtkPVRenderView; see the constructor).
  vtkSmartPointer<vtkImageProcessingPass> ToneMapping;
  bool UseToneMapping = false;

  // The additional lights, in the order the Light Inspector added them.
  std::vector<vtkWeakPointer<vtkLight>> Lights;
  // ShaftLights: 1-based indices into Lights.
  std::vector<int> ShaftLights;

  // Sampling as set (the preset, when one is chosen, overrides these in the pass); they start
  // at the pass's own defaults.
  int NumberOfSlices = this->Shafts->GetNumberOfSlices();
  int ShadowMapSize = this->Shafts->GetShadowMapSize();
  bool AutomaticSliceCount = this->Shafts->GetAutomaticSliceCount();
  int MaximumNumberOfSlices = this->Shafts->GetMaximumNumberOfSlices();
  bool Jitter = this->Shafts->GetJitter();
  int BlurRadius = this->Shafts->GetBlurRadius();
  int DownsampleFactor = this->Shafts->GetDownsampleFactor();
  int AccumulationPrecision = this->Shafts->GetAccumulationPrecision();
  // The MediumDensity property's pipeline output, set aside while a volume is the medium.
  vtkSmartPointer<vtkAlgorithmOutput> DensityConnection;
  // A preset may choose the method (the ray march's steps and interleaving) too.
  int Method = this->Shafts->GetMethod();
  int NumberOfSteps = this->Shafts->GetNumberOfSteps();
  int InterleaveSize = this->Shafts->GetInterleaveSize();

  std::string CookieFileName;
  double ViewTime = 0.0;

  // Whether the processes' scene depths are combined in this render (image pieces, or IceT's
  // ordered compositing, which composites no depth).
  bool ShareSceneDepth = false;
  bool OrderedCompositing = false;
  // The renderer's own FXAA was turned off for this render (AboutToRenderOnLocalProcess).
  bool RestoreRendererFXAA = false;
  // ExactFinish as set, and whether the view said it is off under MPI.
  bool ExactFinish = false;
  bool WarnedExactFinish = false;

  // FitMediumToScene: whether it is on and was handed to the pass, and the coefficients and
  // exposure as given, with the pass's defaults (a value other than its default is the user's).
  bool FitMedium = true;
  bool FitAsked = false;
  double Scattering[3] = { 0.0, 0.0, 0.0 };
  double Absorption[3] = { 0.0, 0.0, 0.0 };
  double Exposure = this->Shafts->GetExposure();
  double DefaultScattering[3] = { 0.0, 0.0, 0.0 };
  double DefaultAbsorption[3] = { 0.0, 0.0, 0.0 };
  double DefaultExposure = this->Shafts->GetExposure();

  Internals()
  {
    this->Shafts->GetMedium()->GetScatteringCoefficient(this->DefaultScattering);
    this->Shafts->GetMedium()->GetAbsorptionCoefficient(this->DefaultAbsorption);
    std::copy(this->DefaultScattering, this->DefaultScattering + 3, this->Scattering);
    std::copy(this->DefaultAbsorption, this->DefaultAbsorption + 3, this->Absorption);
  }

  // The coefficients or the exposure as given (all of them, or the user's only).
  void GiveMedium(bool usersOnly)
  {
    vtkLightShaftMedium* medium = this->Shafts->GetMedium();
    const bool coefficients =
      !std::equal(this->Scattering, this->Scattering + 3, this->DefaultScattering) ||
      !std::equal(this->Absorption, this->Absorption + 3, this->DefaultAbsorption);
    if (!usersOnly || coefficients)
    {
      medium->SetScatteringCoefficient(this->Scattering);
      medium->SetAbsorptionCoefficient(this->Absorption);
    }
    if (!usersOnly || this->Exposure != this->DefaultExposure)
    {
      this->Shafts->SetExposure(this->Exposure);
    }
  }
};

#endif
