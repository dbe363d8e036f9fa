// The rubber duck seen directly: its mesh of ellipsoids (duck.rs) turned and moved to its
// pose, lit like the sphere (caustics under water, ambient occlusion near the walls) with a
// glossy highlight on the rubber, and dimmed by any water between it and the eye.

struct DuckOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) colour: vec3<f32>,
};

@vertex
fn vs_duck(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) colour: vec3<f32>) -> DuckOut {
    var out: DuckOut;
    out.world = duck_rotation() * position + scene.duck_pose[3].xyz;
    out.normal = duck_rotation() * normal;
    out.colour = colour;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_duck(in: DuckOut) -> @location(0) vec4<f32> {
    let view = normalize(in.world - scene.eye.xyz);
    return seen_directly(duck_colour(in.world, normalize(in.normal), in.colour, view), in.world);
}
