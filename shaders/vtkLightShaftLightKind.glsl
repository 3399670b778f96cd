// Shared by the light-shaft shaders: where a light shines and how far a point is from it, per
// kind (#defines LIGHTSHAFT_POINT, LIGHTSHAFT_DIRECTIONAL; neither: a spotlight), in view
// coordinates (VC). Included once however many chunks ask for it.
#ifndef LIGHTSHAFT_LIGHT_CHUNK
#define LIGHTSHAFT_LIGHT_CHUNK

uniform vec3 lightPositionVC; // spot, point: the light; directional: a point of its plane
uniform vec3 lightAxisVC;     // unit: the spot's axis; the direction a directional light travels
uniform float cosConeAngle;   // spot: cos of the cone half-angle

// r: the distance from the light, or from a directional light's plane (its extinction leg).
float lightShaftLightDistance(vec3 pointVC)
{
#ifdef LIGHTSHAFT_DIRECTIONAL
  return dot(pointVC - lightPositionVC, lightAxisVC);
#else
  return length(pointVC - lightPositionVC);
#endif
}

// The unit direction the light travels at pointVC (r: its light distance).
vec3 lightShaftLightDirection(vec3 pointVC, float r)
{
#ifdef LIGHTSHAFT_DIRECTIONAL
  return lightAxisVC;
#else
  return (pointVC - lightPositionVC) / max(r, 1e-30);
#endif
}

// A view ray relative to the light: x = t + b is measured from the foot of the perpendicular
// from the light (at `foot`, relative to the light), which keeps the cone quadratic's
// coefficients of the size of the ray's distance from the light. A directional light has no
// apex: x = t (b = 0) and `foot` is the ray's origin relative to the light's plane point.
void lightShaftRayFoot(vec3 originVC, vec3 dirVC, out float b, out vec3 foot)
{
  vec3 m = originVC - lightPositionVC;
#ifdef LIGHTSHAFT_DIRECTIONAL
  b = 0.0;
  foot = m;
#else
  b = dot(m, dirVC);
  foot = m - b * dirVC;
#endif
}

// The parameter interval of the line m + x dir (m relative to the light's position) where the
// light shines: the spot cone's forward nappe (convex: half-angle < 90 degrees, so one
// interval), everywhere for a point light, beyond a directional light's plane.
bool lightShaftLightInterval(vec3 m, vec3 dir, out float t0, out float t1)
{
  float lo = -3.0e38;
  float hi = 3.0e38;
#ifndef LIGHTSHAFT_POINT
  float da = dot(dir, lightAxisVC);
  float ma = dot(m, lightAxisVC);
  // Forward half-space: (m + t dir) . axis >= 0.
  if (abs(da) > 1e-12)
  {
    float tPlane = -ma / da;
    if (da > 0.0)
    {
      lo = tPlane;
    }
    else
    {
      hi = tPlane;
    }
  }
  else if (ma < 0.0)
  {
    return false;
  }
#endif
#if !defined(LIGHTSHAFT_POINT) && !defined(LIGHTSHAFT_DIRECTIONAL)
  // Double cone: A t^2 + B t + C >= 0.
  float c2 = cosConeAngle * cosConeAngle;
  float qa = da * da - c2;
  float qb = 2.0 * (da * ma - c2 * dot(dir, m));
  float qc = ma * ma - c2 * dot(m, m);
  if (abs(qa) < 1e-7)
  {
    if (abs(qb) > 1e-30)
    {
      float tLine = -qc / qb;
      if (qb > 0.0)
      {
        lo = max(lo, tLine);
      }
      else
      {
        hi = min(hi, tLine);
      }
    }
    else if (qc < 0.0)
    {
      return false;
    }
  }
  else
  {
    float disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0)
    {
      if (qa < 0.0)
      {
        return false;
      }
    }
    else
    {
      float q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      float rootA = q / qa;
      float rootB = (q != 0.0) ? qc / q : rootA;
      float tIn = min(rootA, rootB);
      float tOut = max(rootA, rootB);
      if (qa < 0.0)
      {
        lo = max(lo, tIn);
        hi = min(hi, tOut);
      }
      else
      {
        // Outside [tIn, tOut]: keep the piece on the forward nappe's side.
        bool before = lo <= tIn;
        bool after = hi >= tOut;
        if (before && !after)
        {
          hi = min(hi, tIn);
        }
        else if (after && !before)
        {
          lo = max(lo, tOut);
        }
        else if (!before && !after)
        {
          return false;
        }
        else if (ma + 0.5 * (lo + tIn) * da >= 0.0 && tIn - lo >= hi - tOut)
        {
          hi = min(hi, tIn);
        }
        else
        {
          lo = max(lo, tOut);
        }
      }
    }
  }
#endif
  t0 = lo;
  t1 = hi;
  return t1 > t0;
}

#endif
