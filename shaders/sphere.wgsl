// The sphere seen directly: a unit mesh scaled and moved to the sphere's centre, shaded by
// the shared sphere lighting (caustics under water, ambient occlusion near walls).

struct SphereOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_sphere(@location(0) unit: vec3<f32>) -> SphereOut {
    var out: SphereOut;
    out.world = scene.sphere.xyz + unit * scene.sphere.w;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_sphere(in: SphereOut) -> @location(0) vec4<f32> {
    return seen_directly(sphere_colour(in.world, normalize(in.world - scene.eye.xyz)), in.world);
}
