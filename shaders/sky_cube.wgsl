// The daylight sky, painted once per cube face whenever the sun moves: Preetham's analytic sky
// (sky.rs makes the Perez coefficients and zenith values; here F(θ, γ) per texel, xyY to
// linear RGB), soft clouds on a virtual plane lit by the sun, and the ground below the horizon
// as a dim haze. Stored as radiance / SKY_RANGE in 8-bit sRGB; alpha carries the cloud cover
// that dims the sun's disk (added analytically where the sky is looked up: scene.wgsl).

struct SkyFace {
    sun: vec4<f32>,        // xyz unit vector towards the sun; w unused
    face: vec4<f32>,       // x cube face index 0..5 (+X, -X, +Y, -Y, +Z, -Z)
    perez_y: vec4<f32>,    // Perez A..D for luminance Y
    perez_cx: vec4<f32>,   // Perez A..D for chromaticity x
    perez_cy: vec4<f32>,   // Perez A..D for chromaticity y
    perez_e: vec4<f32>,    // Perez E for Y, x, y
    zenith: vec4<f32>,     // Y (scene units), x, y at the zenith over F(0, θ_s)
    sun_light: vec4<f32>,  // rgb the sun's light (scene units)
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

fn perez(c: vec4<f32>, e: f32, cos_theta: f32, gamma: f32) -> f32 {
    let cg = cos(gamma);
    return (1.0 + c.x * exp(c.y / max(cos_theta, 0.01))) * (1.0 + c.z * exp(c.w * gamma) + e * cg * cg);
}

fn xyy_to_rgb(x: f32, y: f32, lum: f32) -> vec3<f32> {
    let cx = x * lum / max(y, 1.0e-4);
    let cz = (1.0 - x - y) * lum / max(y, 1.0e-4);
    return max(vec3<f32>(
        3.2406 * cx - 1.5372 * lum - 0.4986 * cz,
        -0.9689 * cx + 1.8758 * lum + 0.0415 * cz,
        0.0557 * cx - 0.2040 * lum + 1.0570 * cz,
    ), vec3<f32>(0.0));
}

fn daylight(dir: vec3<f32>) -> vec3<f32> {
    let cos_theta = max(dir.y, 0.0);
    let gamma = acos(clamp(dot(dir, sky.sun.xyz), -1.0, 1.0));
    let lum = sky.zenith.x * perez(sky.perez_y, sky.perez_e.x, cos_theta, gamma);
    let x = sky.zenith.y * perez(sky.perez_cx, sky.perez_e.y, cos_theta, gamma);
    let y = sky.zenith.z * perez(sky.perez_cy, sky.perez_e.z, cos_theta, gamma);
    return xyy_to_rgb(x, y, lum);
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
    let fade = smoothstep(0.04, 0.3, dir.y);
    return smoothstep(0.56, 0.86, sum) * fade;
}

@fragment
fn fs_sky_face(in: FullscreenOut) -> @location(0) vec4<f32> {
    let dir = normalize(face_direction(i32(sky.face.x), in.uv));
    let above = vec3<f32>(dir.x, max(dir.y, 0.0), dir.z);
    var colour = daylight(normalize(above + vec3<f32>(0.0, 1.0e-3, 0.0)));
    if (dir.y < 0.0) {
        // The ground far away: the horizon's haze over a dim land.
        colour = mix(colour, colour * vec3<f32>(0.42, 0.45, 0.40), smoothstep(0.0, 0.08, -dir.y));
    }
    let c = clouds(dir);
    // Clouds: white where the sun lights them, greyer away from it, lit by the sky below too.
    let cos_sun = max(dot(dir, sky.sun.xyz), 0.0);
    let cloud = sky.sun_light.rgb * (0.10 + 0.08 * pow(cos_sun, 4.0)) + 0.6 * daylight(vec3<f32>(0.0, 1.0, 0.0));
    colour = mix(colour, cloud, c * 0.8);
    return vec4<f32>(min(colour / SKY_RANGE, vec3<f32>(1.0)), c);
}
