#!/usr/bin/env bash
# Compiles every shader matc emits for the examples with the glslangValidator CLI (GLSL and HLSL
# front ends, independent of matc's in-process compile) and validates every .spv with spirv-val.
# Usage: check_emitted_shaders.sh MATC EXAMPLES_DIR
set -euo pipefail
matc=$1
examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$matc" -q -o "$work/out" --embed-lut --embed-lut-size 8 --lut-size 16 --lut-samples 32 \
  "$examples"/*.json
cd "$work/out"

failed=0
checked=0
check() {  # description, command...
  local what=$1
  shift
  if "$@" >"$work/log" 2>&1; then
    checked=$((checked + 1))
  else
    echo "FAIL: $what"
    cat "$work/log"
    failed=$((failed + 1))
  fi
}

for snippet in *.glsl; do
  [ "$snippet" = matc_fresnel.glsl ] && continue
  name=${snippet%.glsl}
  # A coated material's (docs/coating.md) preintegrated base takes the coat's texel and NdotV
  # too, and it has the coat lobe's function beside it.
  glsl_f="matc_fresnel_$name(values[i].x)"
  hlsl_f="matc_fresnel_$name(v.x)"
  glsl_fbar="matc_fresnel_preintegrated_$name(bbar)"
  hlsl_fbar="matc_fresnel_preintegrated_$name(bbar)"
  # A filmed metal's (docs/thin-film.md) take its own table's texels.
  if grep -q "film_texel" "$snippet"; then
    glsl_f="matc_fresnel_$name(MATC_FILM_FRESNEL(matc_film, values[i].x))"
    hlsl_f="matc_fresnel_$name(matc_film_fresnel(matc_film, matc_lut_sampler, v.x))"
    glsl_fbar="matc_fresnel_preintegrated_$name(MATC_FILM_PREINTEGRATED(matc_film, values[i].y, values[i].z))"
    hlsl_fbar="matc_fresnel_preintegrated_$name(matc_film_preintegrated(matc_film, matc_lut_sampler, v.y, v.z))"
  fi
  # A filmed metal under a coat (docs/thin-film.md): the base lobe from its table, the coat lobe's
  # function beside it.
  if grep -q "matc_coat_fresnel_$name" "$snippet" && grep -q "film_texel" "$snippet"; then
    glsl_fbar="($glsl_fbar + matc_coat_fresnel_$name(values[i].x))"
    hlsl_fbar="($hlsl_fbar + matc_coat_fresnel_$name(v.x))"
  elif grep -q "matc_coat_fresnel_$name" "$snippet"; then
    glsl_fbar="(matc_fresnel_preintegrated_$name(bbar, bbar, values[i].y) + matc_coat_fresnel_$name(values[i].x))"
    hlsl_fbar="(matc_fresnel_preintegrated_$name(bbar, bbar, v.y) + matc_coat_fresnel_$name(v.x))"
  fi
  # GLSL: a compute shader calling both of the material's functions, for Vulkan (SPIR-V) ...
  {
    echo "#version 450"
    cat matc_fresnel.glsl "$snippet"
    cat <<GLSL
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
layout(binding = 1) uniform sampler2D matc_lut;
layout(binding = 2) uniform sampler2D matc_film;
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 bbar = texture(matc_lut, matc_lut_texcoord(values[i].y, values[i].z));
  values[i] = vec4($glsl_f + $glsl_fbar *
                   matc_energy_compensation(matc_coefficients_$name, bbar) +
                   matc_preintegrated_basis_embedded(values[i].y, values[i].z).xyz, 1.0);
}
GLSL
  } >"$work/$name.comp"
  check "$name.glsl (Vulkan GLSL 450)" glslangValidator -V --target-env vulkan1.1 \
    "$work/$name.comp" -o "$work/$name.comp.spv"
  check "$name.comp.spv" spirv-val --target-env vulkan1.1 "$work/$name.comp.spv"
  # ... and as desktop OpenGL GLSL 3.30, which the snippets promise too.
  sed -e 's/^#version 450/#version 330/' -e '/local_size_x/d' -e '/buffer Data/d' \
    -e 's/gl_GlobalInvocationID.x/0u/' -e 's/values\[i\]/gl_FragCoord/g' \
    -e 's/^  gl_FragCoord = vec4/  matc_colour = vec4/' "$work/$name.comp" |
    sed -e '/^layout(binding = 1)/c uniform sampler2D matc_lut;\nout vec4 matc_colour;' \
      -e '/^layout(binding = 2)/c uniform sampler2D matc_film;' \
      >"$work/$name.frag"
  check "$name.glsl (GLSL 330)" glslangValidator "$work/$name.frag"

  # HLSL through glslang's HLSL front end.
  {
    cat matc_fresnel.hlsl "$name.hlsl"
    cat <<HLSL
RWStructuredBuffer<float4> values : register(u0);
Texture2D<float4> matc_lut : register(t1);
SamplerState matc_lut_sampler : register(s2);
Texture2D<float4> matc_film : register(t3);
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  float4 v = values[id.x];
  float4 bbar = matc_lut.SampleLevel(matc_lut_sampler, matc_lut_texcoord(v.y, v.z), 0.0);
  values[id.x] = float4($hlsl_f + $hlsl_fbar *
                        matc_energy_compensation(matc_coefficients_$name, bbar) +
                        matc_preintegrated_basis_embedded(v.y, v.z).xyz, 1.0);
}
HLSL
  } >"$work/$name.hlsl"
  check "$name.hlsl (HLSL)" glslangValidator -V -D -e main -S comp --target-env vulkan1.1 \
    "$work/$name.hlsl" -o "$work/$name.hlsl.spv"
  check "$name.hlsl.spv" spirv-val --target-env vulkan1.1 "$work/$name.hlsl.spv"
done

# The emitted SPIR-V: library modules (Linkage), so validated under the universal 1.3 rules.
for module in *.spv; do
  check "$module" spirv-val --target-env spv1.3 "$module"
done

echo "check_emitted_shaders: $checked passed, $failed failed"
[ "$failed" -eq 0 ]
