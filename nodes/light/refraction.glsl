void fg_light_refraction(vec3 normal, vec3 to_camera, float ior, vec3 color, float depth, float strength,
                         OUT(vec3) transmission, OUT(float) refractive_index, OUT(vec3) absorption)
{
    // What Fresnel's law does not reflect enters the body.
    transmission = vec3(strength * (1.0 - fg_fresnel_dielectric(dot(normal, to_camera), ior)));
    refractive_index = ior;
    // Beer-Lambert: white light takes `color` after `depth` inside, so its coefficient is -ln(color) / depth.
    absorption = -log(max(color, vec3(1e-6))) / max(depth, 1e-6);
}
