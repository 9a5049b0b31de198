# Smoke test of candela-report: a quick run writes the page; every row is there and every
# number in the main table is finite. Timing values are never checked.
# Figures of an earlier run must not pass for this run's.
get_filename_component(folder ${OUT} DIRECTORY)
file(GLOB stale ${folder}/*.svg)
if(stale)
  file(REMOVE ${stale})
endif()
execute_process(COMMAND ${REPORT} --quick --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "candela-report --quick failed (${rc})")
endif()
file(READ ${OUT} page)
foreach(row
    "| Fresnel: Schlick with SG exponent"
    "| Vis: Schlick-Smith, k = alpha / 2"
    "| EnvBRDFApprox (Karis 2014, Physically Based Shading on Mobile)"
    "| eq. 8 LUT, 128x128"
    "| eq. 8 by Monte Carlo at run time"
    "| Sphere light: representative point"
    "| Tube light: closest point to R"
    "| Rect light: representative point (Drobot 2014, GPU Pro 5), diffuse"
    "| Rect light: LTC (polygon integral, fitted specular), specular"
    "| Disk light: representative point (Drobot 2014, GPU Pro 5), specular"
    "| Disk light: LTC (Heitz-Hill disk integral, fitted specular), diffuse"
    "| Textured rect light: LTC, exact integral per image cell (8 x 8 specular, 4 x 4 diffuse), specular"
    "| Windowed falloff (eq. 9)"
    "| Split-sum IBL"
    "| Mobile IBL"
    "| Clustered light culling"
    "| Shadows: PCF, 2x2 comparison-sampler taps (point light)"
    "| Shadows: blocker search + penumbra filter (sphere light)"
    "| Shadows: 2 sun cascades (PCF)"
    "| Shadows: 4 sun cascades (PCF)"
    "| Hair self-shadowing: hair depth map"
    "| Hair without self-shadowing, 600 strands"
    "| TAA after 16 static frames (Halton 16)"
    "| Anisotropic IBL (bent reflection vector"
    "| Clear-coat split sum"
    "| Material layers: 4 layers blended in the G-buffer pass"
    "| GTAO, radius 1.5 m, 4 slices, temporal, 16 frames"
    "| GPU skinning pass (fp32 compute"
    "| GGX D (eq. 3) in fp32 at kMinRoughness"
    "## GGX peak in fp32 near kMinRoughness"
    "## Sphere lights:"
    "## Tube lights:"
    "| Sphere light, --area-lights representative"
    "| Sphere light, --area-lights ltc"
    "| Tube light, --area-lights representative"
    "| Tube light of radius 0.30 m, --area-lights ltc"
    "| Light shafts: epipolar, 160x96"
    "| Light shafts: min/max tree, 160x96"
    "## Sphere lights: representative point / LTC"
    "## Tube lights: representative point / LTC"
    "## Figures"
    "](speed-vs-error-frontier.svg)"
    "](area_light_sphere_ltc.svg)")
  string(FIND "${page}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "row missing from ${OUT}: ${row}")
  endif()
endforeach()
# The figures the page embeds are written beside it, as SVG.
foreach(figure speed-vs-error-frontier area_light_sphere_representative area_light_sphere_ltc
        area_light_tube_representative area_light_tube_ltc area_light_rect_representative
        area_light_rect_ltc area_light_disk_representative area_light_disk_ltc
        area_light_textured_rect_representative area_light_textured_rect_ltc
        area_light_textured_rect_steps_035_representative area_light_textured_rect_steps_035_ltc)
  if(NOT EXISTS ${folder}/${figure}.svg)
    message(FATAL_ERROR "figure missing beside ${OUT}: ${figure}.svg")
  endif()
  file(READ ${folder}/${figure}.svg svg)
  if(NOT svg MATCHES "^<\\?xml" OR NOT svg MATCHES "</svg>\n$")
    message(FATAL_ERROR "${figure}.svg is not a complete SVG file")
  endif()
endforeach()
# formatNumber writes non-finite values as nan / inf.
if(page MATCHES "[| (]-?(nan|inf)[ |)%]")
  message(FATAL_ERROR "non-finite number in ${OUT}")
endif()
message(STATUS "candela-report smoke: every row present, all numbers finite")
