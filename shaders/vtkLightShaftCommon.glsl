// Shared by the slice and composite shaders: the pixel-centre view ray of the scene camera.
// All positions are in view coordinates (VC), where the camera plane is z = 0.

uniform mat4 invProjectionDCVC; // inverse of the scene camera's projection (DC -> VC)
uniform vec2 targetSize;        // size of the off-screen targets in pixels
uniform sampler2D sceneDepth;   // the delegate's depth buffer
// The view depth where a ray that hits no surface ends (vtkLightShaftModel::BackdropDepth: the
// scene's far side, whatever the camera's clipping range).
uniform float backdropDepthVC;

// Ray through the point `ndc` of the screen (or the centre of pixel `fragCoord`, in target
// pixels, whose NDC it also returns): origin on the camera plane (the eye for a perspective
// camera), unit direction.
void lightShaftViewRayNDC(vec2 ndc, out vec3 originVC, out vec3 dirVC)
{
  vec4 nearVC = invProjectionDCVC * vec4(ndc, -1.0, 1.0);
  vec4 farVC = invProjectionDCVC * vec4(ndc, 1.0, 1.0);
  nearVC.xyz /= nearVC.w;
  farVC.xyz /= farVC.w;
  dirVC = normalize(farVC.xyz - nearVC.xyz);
  originVC = nearVC.xyz - dirVC * (nearVC.z / dirVC.z);
}

void lightShaftViewRay(vec2 fragCoord, out vec3 originVC, out vec3 dirVC, out vec2 ndc)
{
  ndc = 2.0 * fragCoord / targetSize - 1.0;
  lightShaftViewRayNDC(ndc, originVC, dirVC);
}

// Distance along the ray from its origin to the surface whose depth-buffer value is `depth`
// (1 = nothing drawn: the backdrop).
float lightShaftSurfaceDistance(vec2 ndc, float depth, vec3 dirVC)
{
  if (depth >= 1.0)
  {
    return backdropDepthVC / -dirVC.z;
  }
  vec4 surfaceVC = invProjectionDCVC * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return (surfaceVC.z / surfaceVC.w) / dirVC.z;
}

// View depth (distance in front of the camera plane) of a depth-buffer value at `ndc`.
float lightShaftViewDepth(vec2 ndc, float depth)
{
  if (depth >= 1.0)
  {
    return backdropDepthVC;
  }
  vec4 pointVC = invProjectionDCVC * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return -pointVC.z / pointVC.w;
}
