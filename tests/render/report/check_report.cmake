# Smoke test of candela-report: a quick run writes the page; every row is there and every
# number in the main table is finite. Timing values are never checked.
execute_process(COMMAND ${REPORT} --quick --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "candela-report --quick failed (${rc})")
endif()
file(READ ${OUT} page)
foreach(row
    "| Fresnel: Schlick with SG exponent"
    "| Vis: Schlick-Smith, k = alpha / 2"
    "| EnvBRDFApprox (seed 001, mobile)"
    "| eq. 8 LUT, 128x128"
    "| eq. 8 by Monte Carlo at run time"
    "| Sphere light: representative point"
    "| Tube light: closest point to R"
    "| Rect light: representative point (seed 004 section 1), diffuse"
    "| Rect light: LTC (polygon integral, fitted specular), specular"
    "| Disk light: representative point (seed 004 section 1), specular"
    "| Disk light: LTC (Heitz-Hill disk integral, fitted specular), diffuse"
    "| Windowed falloff (eq. 9)"
    "| Split-sum IBL"
    "| Mobile IBL"
    "| Clustered light culling"
    "| Shadows: PCF, 2x2 comparison-sampler taps (point light)"
    "| Shadows: blocker search + penumbra filter (sphere light)"
    "| Shadows: 2 sun cascades (PCF)"
    "| Shadows: 4 sun cascades (PCF)"
    "| TAA after 16 static frames (Halton 16)"
    "| Anisotropic IBL (bent reflection vector"
    "| Clear-coat split sum"
    "| Material layers: 4 layers blended in the G-buffer pass"
    "| GTAO, radius 1.5 m, 4 slices, temporal, 16 frames"
    "| GPU skinning pass (fp32 compute"
    "| GGX D (eq. 3) in fp32 at kMinRoughness"
    "## GGX peak in fp32 near kMinRoughness"
    "## Sphere lights:"
    "## Tube lights:")
  string(FIND "${page}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "row missing from ${OUT}: ${row}")
  endif()
endforeach()
# formatNumber writes non-finite values as nan / inf.
if(page MATCHES "[| (]-?(nan|inf)[ |)%]")
  message(FATAL_ERROR "non-finite number in ${OUT}")
endif()
message(STATUS "candela-report smoke: every row present, all numbers finite")
