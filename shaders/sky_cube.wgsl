// Procedural sky, rendered once per cube face whenever the sun moves: a gradient from a
// pale horizon to a deep zenith, stone ground below the horizon, soft clouds on a virtual
// plane, and a glow around the sun. 8-bit sRGB (cheap to sample); the sun's HDR disk is added
// analytically where the sky is looked up (scene.wgsl, sky_colour), and alpha carries the
// cloud cover that dims it.

struct SkyFace {
    sun: vec4<f32>,   // xyz unit vector towards the sun
    face: vec4<f32>,  // x cube face index 0..5 (+X, -X, +Y, -Y, +Z, -Z)
};
@group(0) @binding(0) var<uniform> sky: SkyFace;

// Direction through a cube face texel; uv in 0..1, v downwards (standard cube layout).
fn face_direction(face: i32, uv: vec2<f32>) -> vec3<f32> {
    let u = uv.x * 2.0 - 1.0;
    let v = uv.y * 2.0 - 1.0;
    switch face {
        case 0: { return vec3<f32>(1.0, -v, -u); }
        case 1: { return vec3<f32>(-1.0, -v, u); }
        case 2: { return vec3<f32>(u, 1.0, v); }
        case 3: { return vec3<f32>(u, -1.0, -v); }
        case 4: { return vec3<f32>(u, -v, 1.0); }
        default: { return vec3<f32>(-u, -v, -1.0); }
    }
}

fn clouds(dir: vec3<f32>) -> f32 {
    if (dir.y <= 0.0) {
        return 0.0;
    }
    let plane = dir.xz / (dir.y + 0.15) * 1.6;
    var p = vec3<f32>(plane.x, 0.0, plane.y);
    var sum = 0.0;
    var amp = 0.5;
    for (var i = 0; i < 5; i++) {
        sum += amp * value_noise(p);
        p = p * 2.03 + vec3<f32>(1.7, 9.2, 3.1);
        amp *= 0.5;
    }
    let fade = smoothstep(0.02, 0.25, dir.y);
    return smoothstep(0.52, 0.82, sum) * fade;
}

@fragment
fn fs_sky_face(in: FullscreenOut) -> @location(0) vec4<f32> {
    let dir = normalize(face_direction(i32(sky.face.x), in.uv));
    let sun = sky.sun.xyz;
    let zenith = vec3<f32>(0.08, 0.22, 0.62);
    let horizon = vec3<f32>(0.58, 0.72, 0.88);
    // Below the horizon: a warm stone plaza fading into haze at the horizon.
    let haze = vec3<f32>(0.66, 0.70, 0.72);
    let stone = vec3<f32>(0.52, 0.47, 0.40);
    var colour: vec3<f32>;
    if (dir.y >= 0.0) {
        colour = mix(horizon, zenith, pow(dir.y, 0.45));
    } else {
        colour = mix(mix(horizon, haze, smoothstep(0.0, 0.02, -dir.y)), stone, smoothstep(0.01, 0.25, -dir.y));
    }
    let cos_sun = dot(dir, sun);
    // Glow around the sun, stronger near the horizon-ward haze.
    colour += vec3<f32>(1.0, 0.85, 0.6) * (0.35 * pow(max(cos_sun, 0.0), 48.0) + 0.12 * pow(max(cos_sun, 0.0), 6.0));
    let c = clouds(dir);
    let cloud_colour = vec3<f32>(0.95, 0.95, 0.97) * (0.75 + 0.25 * max(cos_sun, 0.0));
    colour = mix(colour, cloud_colour, c * 0.85);
    return vec4<f32>(colour, c);
}
