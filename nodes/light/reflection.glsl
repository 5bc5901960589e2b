void fg_light_reflection(vec3 normal, vec3 to_camera, float ior, vec3 tint, float strength, OUT(vec3) reflection)
{
    reflection = tint * (strength * fg_fresnel_dielectric(dot(normal, to_camera), ior));
}
