// Light above the water and at the surface: the sky, the sun's highlight, Fresnel
// reflectance, and Beer–Lambert absorption with scattering along a path through water.

// The sky cubemap (radiance / SKY_RANGE) plus the sun's disk (the sun_size parameter across,
// HDR so its reflections stay bright), dimmed where the cubemap's alpha says clouds cover it.
fn sky_colour(dir: vec3<f32>) -> vec3<f32> {
    let sky = textureSampleLevel(sky_cube, clamp_sampler, dir, 0.0);
    let disk = smoothstep(scene.optics.y, scene.optics.z, dot(dir, scene.sun.xyz));
    // Seen in rippled water the disk is spread as the highlight is (specular_spread), so it
    // does not sparkle from pixel to pixel.
    let spread = specular_spread * specular_spread;
    return sky.rgb * SKY_RANGE + sun_light() * SUN_DISK_RADIANCE * spread * disk * (1.0 - 0.8 * sky.a);
}

// Specular reflection of the sun on water, sharper and brighter than the cubemap's disk
// can hold at its resolution: the glitter on ripples. dir: a ray leaving the surface into
// the air. Phong: cos^s of the angle between dir (the mirrored view ray) and the sun.
// Blinn-Phong: cos^s of the angle between the surface normal and the half vector of the
// directions to the eye and to the sun, for a mirrored ray (`normal` given; a ray refracted
// out of the water passes a zero normal and keeps Phong's lobe).
fn sun_specular(dir: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    var lobe = max(dot(dir, scene.sun.xyz), 0.0);
    if (SPECULAR_MODEL == SPECULAR_BLINN_PHONG) {
        let to_eye = -reflect(dir, normal);
        let half_vector = normalize(to_eye + scene.sun.xyz);
        lobe = select(lobe, max(dot(normal, half_vector), 0.0), dot(normal, normal) > 0.5);
    }
    // Toksvig: where the normals vary within the pixel the lobe widens (specular_spread < 1)
    // and its peak falls, instead of sparkling from pixel to pixel. By the square root of the
    // energy-keeping factor (s' + 2) / (s + 2): the glitter of sub-pixel ripples stays bright.
    let s = scene.optics.x * specular_spread;
    return sun_light() * SUN_GLINT * sqrt((s + 2.0) / (scene.optics.x + 2.0)) * pow(lobe, s);
}

// Fresnel reflectance by this variant's model (FRESNEL_MODEL; the formulas, their sources and
// the tests that hold these pixels to them are in optics.rs). cos_i: cosine of the incidence
// angle; eta: n_from / n_to. Below the surface the approximations take the angle on the air
// side (Snell); total internal reflection stays exact.
fn reflectance(cos_i: f32, eta: f32) -> f32 {
    if (FRESNEL_MODEL == FRESNEL_EXACT) {
        return fresnel(cos_i, eta);
    }
    let ci = clamp(cos_i, 0.0, 1.0);
    let sin_t2 = eta * eta * (1.0 - ci * ci);
    if (sin_t2 >= 1.0) {
        return 1.0;
    }
    let c = select(ci, sqrt(1.0 - sin_t2), eta > 1.0);
    if (FRESNEL_MODEL == FRESNEL_TABLE) {
        // Indexed by the air-side angle (optics::fresnel_table); linear interpolation between
        // the two texels around it, by hand: 32-bit float textures are not filterable everywhere.
        let u = acos(c) / (0.5 * PI) * f32(FRESNEL_TABLE_SIZE - 1);
        let i = min(i32(floor(u)), FRESNEL_TABLE_SIZE - 2);
        let row = select(0, 1, eta > 1.0);
        let a = textureLoad(fresnel_table, vec2<i32>(i, row), 0).r;
        let b = textureLoad(fresnel_table, vec2<i32>(i + 1, row), 0).r;
        return a + (b - a) * (u - f32(i));
    }
    if (FRESNEL_MODEL == FRESNEL_SCHLICK) {
        return SCHLICK_R0 + (1.0 - SCHLICK_R0) * pow(1.0 - c, 5.0);
    }
    if (FRESNEL_MODEL == FRESNEL_INVERSE_POWER) {
        return 1.0 / pow(1.0 + c, INVERSE_POWER_EXPONENT);
    }
    if (FRESNEL_MODEL == FRESNEL_CLAMPED_POWER) {
        return clamp(pow(1.0 - c, CLAMPED_POWER_EXPONENT), CLAMPED_POWER_MIN, CLAMPED_POWER_MAX);
    }
    return 1.0 - c;
}

// Light leaving `far` as it arrives at `near` through the water between them. Beer–Lambert:
// each channel keeps α = exp(-a d) of itself over d metres (red dies first, so long paths turn
// blue-green). With in-scattering (HAS_SCATTERING; seed 001, after Baboud and Décoret) the
// water adds the light it scatters towards the eye, filling in what it absorbed:
// α L + (1 - α) L_s; with VIEW_COLOUR L_s is tinted by the path's angle as seed 002 does.
fn through_water(colour: vec3<f32>, near: vec3<f32>, far: vec3<f32>) -> vec3<f32> {
    let alpha = exp(-scene.absorption.xyz * water_path(near, far, half_width(), depth()));
    if (!HAS_SCATTERING) {
        return colour * alpha;
    }
    var scattered = scene.scatter.xyz;
    if (VIEW_COLOUR) {
        let path = far - near;
        scattered *= mix(GRAZING_TINT, vec3<f32>(1.0), abs(path.y) / max(length(path), 1.0e-6));
    }
    return colour * alpha + (1.0 - alpha) * scattered;
}
