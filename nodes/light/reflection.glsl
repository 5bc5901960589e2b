void fg_light_reflection(vec3 normal, vec3 to_camera, float ior, vec3 tint, float strength, OUT(vec3) reflection)
{
    // Fresnel's equations from air into the medium, both polarisations averaged.
    float cos_i = clamp(dot(normal, to_camera), 0.0, 1.0);
    float sin_t2 = (1.0 - cos_i * cos_i) / (ior * ior);
    float cos_t = sqrt(max(1.0 - sin_t2, 0.0));
    float rs = (cos_i - ior * cos_t) / max(cos_i + ior * cos_t, 1e-12);
    float rp = (cos_t - ior * cos_i) / max(cos_t + ior * cos_i, 1e-12);
    reflection = tint * (strength * 0.5 * (rs * rs + rp * rp));
}
