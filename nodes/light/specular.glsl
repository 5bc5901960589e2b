void fg_light_specular(vec3 normal, vec3 to_camera, vec3 light_dir, float roughness, vec3 reflectance, float strength,
                       OUT(vec3) specular, OUT(vec3) specular_color, OUT(float) lobe_roughness)
{
    vec3 halfway = light_dir + to_camera;
    halfway = halfway * inversesqrt(max(dot(halfway, halfway), 1e-12));
    float nl = max(dot(normal, light_dir), 0.0);
    float nv = max(dot(normal, to_camera), 1e-4);
    float nh = max(dot(normal, halfway), 0.0);
    float vh = max(dot(to_camera, halfway), 0.0);
    float a = roughness * roughness;
    float a2 = a * a;
    float q = nh * nh * (a2 - 1.0) + 1.0;
    float distribution = a2 / (FG_PI * q * q);
    float visibility = 0.5 / max(nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2), 1e-6);
    vec3 fresnel = reflectance + (vec3(1.0) - reflectance) * pow(1.0 - vh, 5.0);
    specular = fresnel * (strength * distribution * visibility * nl);
    // The lobe itself, for the environment's reflection in it (environment.glsl).
    specular_color = reflectance;
    lobe_roughness = roughness;
}
