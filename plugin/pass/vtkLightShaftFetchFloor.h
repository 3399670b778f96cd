/**
 * @class   vtkLightShaftFetchFloor
 * @brief   The "fetch floor": how long a trivial full-screen shader takes to do a given number of
 *          texture fetches per pixel, the bound a fetch-limited pass cannot beat.
 *
 * The slab method does about two fetches per slab and covered pixel (the scene depth and the
 * shadow map); comparing vtkLightShaftPass's time with Measure() for the same number of fetches
 * per pixel says how close to the hardware's texture limit it runs (tests/benchmarks).
 */

#ifndef vtkLightShaftFetchFloor_h
#define vtkLightShaftFetchFloor_h

#include "vtkLightShaftsOpenGLModule.h" // For the export macro
#include "vtkObject.h"                  // For the base class

class vtkRenderWindow;

class VTKLIGHTSHAFTSOPENGL_EXPORT vtkLightShaftFetchFloor : public vtkObject
{
public:
  static vtkLightShaftFetchFloor* New();
  vtkTypeMacro(vtkLightShaftFetchFloor, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Median wall time, in seconds, of `frames` full-screen passes (each finished with glFinish,
   * after one warm-up pass) that each do `fetchesPerPixel` texelFetch from a width x height
   * RGBA32F texture into a width x height RGBA32F target, in `window`'s OpenGL context (render
   * the window once first). Returns -1 on failure. fetchesPerPixel in [0, 100000].
   */
  double Measure(vtkRenderWindow* window, int width, int height, int fetchesPerPixel, int frames);

protected:
  vtkLightShaftFetchFloor() = default;
  ~vtkLightShaftFetchFloor() override = default;

private:
  vtkLightShaftFetchFloor(const vtkLightShaftFetchFloor&) = delete;
  void operator=(const vtkLightShaftFetchFloor&) = delete;
};

#endif
