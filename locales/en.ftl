# wavepool's words in English, the source every other catalogue translates (Project Fluent,
# https://projectfluent.org/fluent/guide/). Written by `wavepool messages` from the tables in
# src/ (src/page_words.rs, the parameter table, the presets): edit the English there. A language
# is added by copying this file to locales/<tag>.ftl, translating each message's text (never its
# id or its { $variables }) and registering the tag in web/i18n.js (LANGUAGES). Units' symbols
# (m/s, Hz, °) and proper names stay as they are.

## The page's own words (web/*.js)

language = Language
controls = Controls
preset = Preset
    .title = Start over from a lesson's settings and view
preset-choose = choose…
preset-applied = Preset { $name } applied.
preset-press-enter = Press Enter to apply the preset { $name }.
reset = Reset
    .title = Back to how this page started: its parameters and view, calm water, the objects in place
defaults = Defaults
    .title = Set every parameter to its default
share-link = Share link
    .title = Copy a link that opens this pool with these parameters and this view
embed-code = Copy embed code
    .title = Copy an <iframe> that shows this pool, as it is now, in another page
link-copied = Link copied.
embed-code-copied = Embed code copied.
fullscreen = Fullscreen
    .title = Fullscreen (Esc leaves it)
play = Play
    .title = Play: start the water and the objects moving
pause = Pause
    .title = Pause: stop the water and the objects
on = on
off = off
dipper = Dipper { $number }
notice-no-gpu = This browser draws without a GPU, so the largest sizes are reduced to keep it responsive: { $sizes }.
notice-slow-resolution = Frames took over a second here: the resolution is now automatic.
notice-slow-grid = Frames took over a second here: the simulation grid is reduced to { $cells } cells.
fresnel-plot = Reflectance against the angle of incidence: the chosen Fresnel model over the exact curve
fresnel-angle = angle of incidence
fresnel-caption = Reflectance: chosen model (blue) over exact (grey); from air solid, from under water dashed; | your view
status-loading = Loading the water…
status-device-lost = The graphics device was lost; restarting…
status-waiting = Waiting for a free GPU context: scroll another water demo on this page out of view.
page-intro = Click or drag on the water to make ripples, drag a floating object to move it, drag elsewhere to turn the camera; scroll or pinch to zoom. With the demo focused: space pauses, G drops the objects, L puts the sun behind you.
page-starting = Starting the water…
page-running = Running on { $api }, { $adapter }.
page-running-unnamed = Running on { $api } (the browser does not tell which GPU).
page-failed = The water could not start here: the box below says why.
costs-gpu = GPU time drawing the water: { $times }.
costs-no-gpu-time = GPU time: this browser does not measure it (no WebGPU timestamps).
costs-between = Between frames: { $times }.
note-flat-under-water = Flat water is an above-water technique: under the water the ray tracer draws.
reading-probe-frequency = Probe frequency
reading-probe-swing = Probe swing
reading-ruler = Ruler
viewer-reset-water = Reset water
    .title = Flatten the water and put the sphere back
viewer-frame = frame: { $cpu } ms CPU, { $between } ms between frames
viewer-gpu = GPU: { $stages }
viewer-gpu-none = GPU time: this device has no timestamp queries
viewer-gpu-waiting = GPU time: waiting for the first timestamps
viewer-costs = drawing the water (caustics + shading): { $costs }
viewer-water = water: { $cells }² cells, { $seconds } s simulated
viewer-adapter = adapter: { $name }
viewer-reset-one = reset
    .title = Reset to default
error-backend-forced = This page asked for { $api } only (backend={ $backend }), and this browser could not start it:
error-backend-forced-fix = Remove backend={ $backend } from the address or the options (or set backend=auto) to let the demo choose a backend this browser has.
error-no-backend = This browser could not start the water demo: neither WebGPU nor WebGL2 worked (graphics acceleration may be turned off in its settings).
error-no-webgpu = WebGPU: this browser does not offer it (navigator.gpu is missing)
error-stopped = The water demo stopped: { $reason }
error-device-lost = The graphics device was lost and could not be restarted: { $reason }
error-crashed = The water demo crashed: { $reason }
error-restart = The water demo could not start again: { $reason }
fallback-picture = A still picture of the water pool (the live demo could not start here)
canvas-label = Water pool. Drag on the water to make ripples, drag the sphere to move it, drag elsewhere to turn the camera. Keys: arrows turn, + and - zoom, Enter makes a drop in the middle, space pauses, G gravity, L light.
embed-title = Interactive water pool (wavepool)
stage-simulation = simulation
stage-caustics = caustics
stage-maps = maps
stage-screen = screen
stage-shading = shading
stage-the-tank = the tank
stage-waves = waves

## The parameter table and the presets
## (written by `wavepool messages` from the tables in src/: edit the English there)

group-water = Water
group-drops = Drops
group-light = Light
group-scene = Scene
group-objects = Objects
group-tank = Tank
group-ambient-waves = Ambient waves
group-optics = Optics
group-water-colour = Water colour
group-simulation = Simulation
group-debug = Debug
group-display = Display
group-flat-water = Flat water
unit-cells = cells

## Water

param-wave_speed = Wave speed
    .help = Speed c of ripples in the wave equation h_tt = c² ∇²h.
param-damping = Damping
    .help = Rate k at which waves lose energy (amplitude decays as exp(-k t / 2)).
param-absorbing_walls = Absorbing walls
    .help = Walls swallow waves in a damping layer along them instead of reflecting them.
param-foam = Foam
    .help = White water where crests fall faster than a quarter of g, where water runs up a wall, and where drops and bodies throw water about; it fades and spreads.
param-foam_decay = Foam lifetime
    .help = Time constant tau of the foam's fading: after tau seconds 37 % of it is left.

## Drops

param-drop_radius = Drop radius
    .help = Radius of the cosine bump a click or drag adds.
param-drop_strength = Drop strength
    .help = Height of the bump at its centre (negative pushes the water down).
param-start_drops = Drops at start
    .help = Drops that fall on the pool when the page opens, so its rings and the caustics they cast show at once (0: the water starts calm).

## Light

param-sun_azimuth = Sun azimuth
    .help = Compass direction of the sun around the pool.
param-sun_elevation = Sun elevation
    .help = Height of the sun above the horizon.
param-sun_size = Sun size
    .help = Angular diameter of the sun's disk in the sky and in its reflections (the real sun: 0.5°).
param-exposure = Exposure
    .help = Brightness of the picture in photographic stops (each +1 doubles the light before the filmic tone curve), on top of the camera's own: a lower sun is exposed for the light it loses.
param-setting = Setting
    .help = Where the pool is: sunk in a paved deck under the sky, or the classic's cut-away box, open at the near walls so you see the water's cross-section.
param-setting-deck = deck
param-setting-cutaway = cutaway
param-caustics = Caustics
    .help = Light focused by the waves onto the floor, walls and sphere.
param-caustic_contrast = Caustic contrast
    .help = How much the caustic lines stand out: the focused light raised to this power. 1 is the light the simulated waves focus, as the caustics map holds it (blurred over its texels, so the lines are wider and dimmer than the sun would draw them); 2 gives them back the brightness of a sunlit pool's net.
param-tile_gloss = Tile gloss
    .help = How much the tiles' glaze mirrors: 1 a ceramic glaze (the sky and the sun's highlight on the tiles above the water, most at their rounded edges), 0 matte tiles.

## Scene

param-scene = Scene
    .help = The pool, the open sea to the horizon under the same sky, or the ripple tank of the school lab with its lamp and screen.
param-scene-pool = pool
param-scene-sea = sea
param-scene-tank = tank
param-sea_wind = Wind
    .help = Wind speed over the sea: stronger wind puts the waves' energy at longer wavelengths.
param-sea_wind_direction = Wind direction
    .help = Direction the wind blows towards, from +x towards +z.
param-sea_wave_height = Wave height
    .help = Significant wave height: four standard deviations of the sea's height (about the mean of the highest third of the waves).
param-sea_choppiness = Choppiness
    .help = How far the water is carried sideways towards the crests, sharpening them (Tessendorf's lambda).
param-sea_fog = Fog
    .help = Haze over the sea, thinning with height, taking water and sky to one colour at the horizon.
param-sea_fog_distance = Fog distance
    .help = Distance over which the haze at sea level dims light to 37 %.
param-sea_island = Island
    .help = An island with beaches, seen through the shallows round it, where the waves foam along the shore: offshore in the haze, or at the shore, its shallows under the patch where clicks make ripples and the ripples' caustics light the sand.
param-sea_island-none = none
param-sea_island-offshore = offshore
param-sea_island-shore = shore
param-sea_grid = Show the grid
    .help = Outline the cells of the grid the sea is drawn on: it is laid over the screen and projected onto the water, so its cells stay about the same size on screen, small near you and long towards the horizon.

## Objects

param-sea_objects = Objects
    .help = What floats in the sea: the pool's sphere, duck and beach ball, as much larger as the patch of simulated water is than the pool. They ride the waves and leave wakes in the patch.
param-sea_objects-none = none
param-sea_objects-sphere = sphere
param-sea_objects-duck = duck
param-sea_objects-both = both
param-sea_objects-ball = ball
param-sea_objects-all = all
param-objects = Objects
    .help = What floats in the pool: any of the sphere, a rubber duck and a beach ball (as a list, e.g. sphere,duck), all or none.
param-objects-none = none
param-objects-sphere = sphere
param-objects-duck = duck
param-objects-both = both
param-objects-ball = ball
param-objects-all = all
param-sphere_radius = Sphere radius
    .help = Radius of the sphere.
param-sphere_density = Sphere density
    .help = Mass per volume; below water's 1000 kg/m³ the sphere floats.
param-duck_density = Duck density
    .help = Mass per volume of the rubber duck: the lighter, the higher it floats.
param-ball_radius = Ball radius
    .help = Radius of the beach ball.
param-ball_density = Ball density
    .help = Mass per volume of the beach ball (air in a thin shell, with sand in it so it bobs less): light, so it rides high on the water.
param-gravity = Gravity
    .help = Let the objects fall, float, bob and drift on the waves (G key); off, they stay where they are put.

## Tank

param-tank_setup = Set-up
    .help = What is in the tank: one dipper, two dippers, a straight bar making plane waves, the bar behind a barrier with one or two slits, the bar and a glass plate whose straight edge bends the waves (refraction), a lens-shaped plate that brings them to a focus, a dipper moving across the tank (Doppler), a curved wall that reflects the bar's waves to a focus (a parabolic mirror), a straight wall facing the bar (standing waves), or a glass prism that turns the bar's waves aside.
param-tank_setup-dipper = dipper
param-tank_setup-two_dippers = two_dippers
param-tank_setup-plane_wave = plane_wave
param-tank_setup-single_slit = single_slit
param-tank_setup-double_slit = double_slit
param-tank_setup-refraction = refraction
param-tank_setup-lens = lens
param-tank_setup-doppler = doppler
param-tank_setup-reflection = reflection
param-tank_setup-standing = standing
param-tank_setup-prism = prism
param-tank_look = Look
    .help = The screen view shows the paper under the tank from above, as the class looks at it; the apparatus shows the lab's tank in 3D: the lamp over the tray, the water, its frame on its legs and the paper on the bench below with the lamp's image on it (drag to walk round it); split shows the two side by side.
param-tank_look-screen = screen
param-tank_look-apparatus = apparatus
param-tank_look-split = split
param-tank_view = View
    .help = What the picture shows: the lamp's light on the screen under the tank (each crest focuses it like a lens into a bright line), the water's height as colour, or the intensity: the height squared, averaged over about the last second.
param-tank_view-screen = screen
param-tank_view-heights = heights
param-tank_view-intensity = intensity
param-tank_tool = Pointer
    .help = What a click or a drag on the tray does: drop small pulses into the water, draw straight walls the waves cannot cross, from where you press to where you let go (a barrier of your own, a reflector, a box), erase back to open water, put the probe where you click, lay a ruler from where you press to where you let go (its length is shown under the tank: lay it across ten crests to measure a wavelength), or move a dipper or the bar: press on it and drag (the dipper you press on then shows its own frequency, amplitude and phase).
param-tank_tool-drops = drops
param-tank_tool-walls = walls
param-tank_tool-erase = erase
param-tank_tool-probe = probe
param-tank_tool-ruler = ruler
param-tank_tool-move = move
param-tank_frequency = Frequency
    .help = How often the dippers (or the bar) go up and down. The wavelength is the speed over the frequency.
param-tank_amplitude = Amplitude
    .help = How far the dippers move the water up and down. A fraction of a millimetre is enough: each crest then focuses the lamp's light near the screen, as in a well-set lab tank; higher waves focus it above the screen, and the lines there break up.
param-tank_dippers = Dippers
    .help = How many dippers stand in a row in the two-dipper set-up, the slit spacing apart.
param-tank_phase = Phase step
    .help = How far each dipper in the row lags its neighbour (a whole cycle is 360°). The waves add up where the lag is made up by the path: the beam turns towards the lagging end, by sin θ = (step/360°) λ / spacing. This is how a phased-array radar or an ultrasound probe steers its beam without moving.
param-tank_detune = Detune
    .help = How much faster each dipper in the row runs than the one before it. Two dippers then beat: where their waves met crest to crest they soon meet crest to trough, and the still lines sweep across the tray as many times a second; a row of four sweeps its beam.
param-tank_amplitude_ratio = Amplitude ratio
    .help = How far each dipper in the row moves the water, as a share of the one before it. With two dippers of unequal strength the still lines are no longer still: where crest meets trough the waves cancel only in part.
param-tank_depth = Water depth
    .help = The water's depth. Here the waves run at shallow water's speed sqrt(g d), faster in deeper water; over a glass plate the water is shallower, so the waves slow there and bend. (A real tank's centimetre ripples are not long against the depth and are pulled by surface tension too, so they run slower and their speed depends on the wavelength; these do not. Each lesson uses one frequency, and what it shows depends only on the wavelengths, so it holds.)
param-tank_size = Tray size
    .help = The side of the square tray.
param-tank_slit_width = Slit width
    .help = The width of each gap in the barrier.
param-tank_slit_spacing = Slit spacing
    .help = The distance between the centres of the two slits, or of the two dippers.
param-tank_lamp_height = Lamp height
    .help = The lamp's height over the water. The screen lies 0.5 m under the tray; a lower lamp spreads the image wider.
param-tank_source_speed = Dipper speed
    .help = How fast the dipper of the Doppler set-up moves across the tank. Ahead of it the waves crowd together, behind it they spread out; faster than the waves (about 0.31 m/s in 10 mm of water), it leaves a bow wave, a V as behind a boat.
param-tank_strobe = Strobe
    .help = Light the tank with flashes this many times a second (0: a steady lamp). At the dippers' frequency every flash finds the waves in the same place, so the pattern stands still and can be measured; a little off it, the waves creep slowly forward or back.
param-tank_lines = Slit lines
    .help = Draw, from between the slits, the directions where theory puts the pattern: for two slits the bright lines, d sin θ = m λ (d the slits' spacing); for one slit the dark ones, w sin θ = m λ (w its width).
param-tank_beaches = Beaches
    .help = Sloping beaches along the walls that swallow the waves (as the foam or mesh strips of a real tank do), or bare walls that reflect them.
param-tank_pulse = Single pulse
    .help = The dippers (or the bar) make one crest and stop, each time this is switched on or the tank is reset, instead of a steady train of waves: watch a single wave spread, reflect and pass through the slits. All the dippers lift the water at the same moment (a phase step, a detune or a dipper's own phase or frequency does not shape a pulse).
param-tank_probe = Probe
    .help = A probe in the water (the ring) and the graph of its height over the last four seconds in the picture's corner; under the tank, the frequency and the swing it reads. Place it with the Pointer's probe tool or the two sliders below.
param-tank_probe_x = Probe across
    .help = The probe's place across the tray, from its middle, to the right as seen from above with the bar at the bottom (kept inside the tray).
param-tank_probe_z = Probe along
    .help = The probe's place along the tray, from its middle towards the far side (kept inside the tray).
param-tank_graph = Intensity graph
    .help = A line across the tray and over it the graph of the intensity along it (the height squared, averaged over about the last second): where the waves add up and where they cancel, as a screen far from the slits would show.
param-tank_graph_z = Graph line
    .help = Where the intensity graph's line crosses the tray, from its middle towards the far side (kept inside the tray).

## Ambient waves

param-ambient = Ambient waves
    .help = A surface that moves on its own under your ripples: none, a sum of sharp-crested travelling sines, the pool's own standing waves (modes) that meet every wall flat, Gerstner waves (the water moves in circles, crests sharpen), or an FFT ocean (thousands of waves from a spectrum).
param-ambient-none = none
param-ambient-sines = sines
param-ambient-modes = modes
param-ambient-gerstner = gerstner
param-ambient-fft = fft
param-wind_speed = Wind speed
    .help = Wind of the Phillips spectrum the waves' amplitudes come from: stronger wind gives the longer waves more of the height.
param-wind_direction = Wind direction
    .help = Direction the wind blows towards, from +x towards +z.
param-wave_height = Wave height
    .help = Significant height H_s of the ambient waves: four times the surface's standard deviation.
param-wave_spread = Spread of directions
    .help = How far (±) the travelling waves' directions stray from the wind's.
param-steepness = Steepness Q
    .help = Gerstner steepness: 0 gives plain sines; towards 1 the water gathers under sharp crests (at 1 they would become cusps).
param-spectrum = Spectrum
    .help = The FFT ocean's wave spectrum: Phillips (Tessendorf's) or JONSWAP (measured seas of limited fetch, a sharper peak; here a 100 m fetch).
param-spectrum-phillips = phillips
param-spectrum-jonswap = jonswap
param-fft_size = FFT grid
    .help = Waves per side of the FFT ocean's lattice: 128 adds ripples down to 6 cm.
param-choppiness = Choppiness
    .help = The FFT ocean's water also moves sideways, gathering under the crests (Tessendorf's choppy waves); 0 is the height field alone.

## Optics

param-fresnel = Fresnel model
    .help = How much of the light the surface reflects at each angle: the exact Fresnel equations, the same from a lookup texture, Schlick's approximation, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) or 1-cos θ.
param-fresnel-exact = exact
param-fresnel-table = table
param-fresnel-schlick = schlick
param-fresnel-inverse_power = inverse_power
param-fresnel-clamped_power = clamped_power
param-fresnel-linear = linear
param-specular = Sun highlight
    .help = Shape of the sun's glint on the water: Phong (reflected ray against the sun) or Blinn-Phong (normal against the half vector), wider at the same shininess.
param-specular-phong = phong
param-specular-blinn_phong = blinn_phong
param-shininess = Shininess
    .help = Exponent s of the highlight's cos^s: higher is a smaller, sharper glint.
param-dispersion = Dispersion
    .help = Red and blue light bend by their own refractive indices (water: 1.331 red, 1.335 green, 1.337 blue), this many times the real spread: coloured fringes at the caustics' edges and at the rim of Snell's window. 0: off.

## Water colour

param-absorption_red = Absorption, red
    .help = Beer-Lambert absorption of red light per metre of water: after d metres exp(-a d) of it is left.
param-absorption_green = Absorption, green
    .help = Beer-Lambert absorption of green light per metre of water: after d metres exp(-a d) of it is left.
param-absorption_blue = Absorption, blue
    .help = Beer-Lambert absorption of blue light per metre of water: after d metres exp(-a d) of it is left.
param-scatter_red = Scattered light, red
    .help = Light the water itself scatters towards you (red, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.
param-scatter_green = Scattered light, green
    .help = Light the water itself scatters towards you (green, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.
param-scatter_blue = Scattered light, blue
    .help = Light the water itself scatters towards you (blue, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.
param-view_colour = Colour by view angle
    .help = The scattered light loses half its green along grazing paths and keeps it looking straight down, as games tint water by the view angle (needs scattered light).

## Simulation

param-sim_size = Grid resolution
    .help = Cells per side of the simulation grid; a change resamples the water, it does not reset it.
param-paused = Paused
    .help = Freeze the water (space bar).

## Debug

param-debug_view = Debug view
    .help = Shows one of the simulation's textures: height (red up, blue down), surface normals, vertical velocity, or the caustics map; or the water's Fresnel reflectance as grey (black 0, white 1); or the ambient waves' spectrum (amplitude per wavevector, log scale, k = 0 in the middle, rings at the 0.9 m and 0.2 m wavelengths).
param-debug_view-off = off
param-debug_view-height = height
param-debug_view-normals = normals
param-debug_view-velocity = velocity
param-debug_view-caustics = caustics
param-debug_view-reflectance = reflectance
param-debug_view-spectrum = spectrum
param-debug_inset = Debug view as inset
    .help = Show the debug view in a corner of the scene (on) or over all of it (off).

## Display

param-quality = Resolution
    .help = Scale of the scene's resolution: fixed, or auto (lowered in steps down to 50% while frames take longer than the frame budget, raised again when there is headroom).
param-quality-auto = auto
param-frame_budget = Frame budget
    .help = Time a frame should take at most; with automatic resolution, slower frames lower the resolution.

## Flat water

param-render_mode = Water rendering
    .help = How the water surface is drawn. raytraced: every pixel of the surface traces its reflected and refracted rays through the pool. flat: the technique games use: the scene is drawn twice more into textures, mirrored in the water plane (reflection) and clipped under it (refraction), and a flat plane blends the two by Fresnel, wobbled by a distortion instead of bent by the waves. It is an above-water technique: under water the ray tracer draws. split: flat on the left, ray-traced on the right of a divider you drag.
param-render_mode-raytraced = raytraced
param-render_mode-flat = flat
param-render_mode-split = split
param-split = Divider
    .help = Where the divider stands, as a fraction of the width from the left: flat water to its left, ray-traced to its right. Drag the divider on the canvas to move it.
param-flat_distortion = Distortion
    .help = What wobbles the flat water's reflection and refraction: dudv, a tiling distortion map (a dUdV map) scrolled over time (clicks make no ripples in it), or ripples, the simulation's own slopes (the same waves as the ray tracer, with faked optics).
param-flat_distortion-dudv = dudv
param-flat_distortion-ripples = ripples
param-flat_strength = Distortion strength
    .help = How far the reflection and refraction textures are shifted by the distortion, as a fraction of the screen. It does not grow with the distance to what is seen, as real refraction does: a rim far above the water wobbles as much as the tiles under it.
param-dudv_speed = Distortion speed
    .help = Tiles of the dudv map scrolled per simulated second (it stops when the water is paused); with the dudv distortion.
param-flat_resolution = Texture resolution
    .help = Size of the reflection and refraction textures against the scene's: smaller is cheaper and blurrier.
param-flat_caustics = Caustics
    .help = Light on the pool under flat water: off (a calm surface's), fake (a highlight where the distortion's normal would send the sun straight down; no focusing, no pass) or real (the ray tracer's caustics map, one more pass).
param-flat_caustics-off = off
param-flat_caustics-fake = fake
param-flat_caustics-real = real
param-flat_soft_edge = Soft edge
    .help = Water shallower than this (along the view) is distorted less, hiding the seam where the flat plane meets the walls; 0 shows the seam.

## Each dipper's own settings in the tank (the group's title: "Dipper" and its number)

param-frequency = Its frequency
    .help = How often this dipper goes up and down. Two dippers a little apart in frequency beat: their still lines sweep across the tray.
param-amplitude = Its amplitude
    .help = How far this dipper moves the water (0 stills it). Where the waves of a strong and a weak dipper meet crest to trough, they cancel only in part.
param-phase = Its phase
    .help = How far this dipper runs ahead of the set phase (a whole cycle is 360°; negative: it lags). Two dippers 180° apart send crest against trough: the middle line between them is still.

## Presets (the name, and what a student reads)

preset-classic = The classic look
    .help = One sphere that stays where it is put (G drops it), reflecting walls, caustics: the pool as the classic WebGL Water shows it.
preset-calm = Calm water
    .help = Nothing in the pool, small drops, waves that die out quickly at absorbing walls: a quiet surface to study one ripple at a time.
preset-busy = A busy pool
    .help = The sphere and the duck floating on fast, lively water with big drops and reflecting walls.
preset-fresnel = Lesson: Fresnel reflectance
    .help = Calm, empty water seen low across the pool, so the angle of incidence runs from about 50° near you to grazing at the far side: switch the Fresnel model and watch the reflection and the plot change.
preset-glint = Lesson: the sun's glint
    .help = Looking towards a low sun: drag across the water to make waves and see Blinn-Phong's glint stretched along the view; switch the highlight to Phong and change the shininess to compare.
preset-breeze = Lesson: ambient waves
    .help = A light breeze makes sharp-crested waves travel across the pool under your ripples; switch Ambient waves to modes to see the pool's own standing waves, which meet every wall flat, to gerstner for water moving in circles, or to fft for a spectrum of thousands of waves (the spectrum debug view shows each model's waves).
preset-ocean = Lesson: an FFT ocean
    .help = Tessendorf's ocean in the pool: a Phillips spectrum of about a thousand waves on a 128-point lattice, summed by an FFT every frame; the debug view shows the spectrum, downwind of the wind's direction.
preset-flat = Lesson: flat water vs ray tracing
    .help = The games' flat water (left) against the ray tracer (right), the sphere half out of the water: drag the divider across the sphere. Left, its submerged half sits unbent at its true depth and the reflections wobble by a fixed shift; right, the water lifts it and bends everything by the waves' slopes. Make ripples and switch the distortion to ripples to see the same waves with faked optics.
preset-lake = Lesson: water colour
    .help = Green lake water: it absorbs red, green and blue faster than the pool's, and scatters a green-blue light of its own, so the deep end turns green instead of dark (turn the scattered light to 0 to see plain Beer-Lambert).
preset-noon = Noon
    .help = The sun almost overhead: a deep blue sky, short shadows, the brightest caustics on the floor.
preset-evening = Evening
    .help = A low warm sun from the side, the picture exposed for it: long shadows across the deck, the water dark where the rim shades it, the far wall lit by the sun's caustics.
preset-sea = Lesson: the open sea
    .help = Open water to the horizon in a moderate breeze: five FFT cascades of different tile sizes, so no pattern repeats; the grid the sea is drawn on is projected from the screen, so its detail follows your view; the haze takes sea and sky to one colour at the horizon (turn Fog off to see the sea's edge); the island ahead stands in turquoise shallows with foam along its shore and is mirrored in the water (turn on Show the grid to see the grid). Click near the middle to make ripples in the patch of simulated water and watch them run out; the rubber duck there, as much larger as the patch is than the pool, rides the waves and leaves a wake: drag it to see one.
preset-shore = Lesson: ripples in the shallows
    .help = The island's beach by the patch of simulated water, in a light breeze under a high sun: the waves' slopes focus the sunlight into a net of caustics on the sand a few metres down. Click the water to make ripples: where the depth is right their rings focus into bright lines on the floor, which show them far better than the surface itself does. The duck's bobbing draws rings of its own, and its shadow lies on the sand.
preset-dawn = A calm sea at dawn
    .help = A low sun ahead over a calm sea: its glint spread into a long path of glitter on the small waves, the sky warm along the horizon.
preset-storm = A storm at sea
    .help = A strong wind raises 5 m waves with sharpened crests under a low sun, in thick haze; the duck is tossed among the whitecaps.
preset-tank = Ripple tank: one dipper
    .help = A school ripple tank seen from above: a dipper bobs ten times a second in the middle of a tray of water 10 mm deep, and the lamp over the tank throws its rings onto the screen below as bright circles, because every crest focuses the light like a lens. Switch the view to the heights to see the waves themselves; change the frequency and watch the rings crowd together (the wavelength is the speed over the frequency).
preset-single_slit = Ripple tank: one slit
    .help = A straight bar makes plane waves that meet a barrier with one gap. Past the gap they spread out in a fan; the narrower the gap against the wavelength, the wider the fan (try the slit width).
preset-double_slit = Ripple tank: two slits
    .help = Plane waves through two gaps 90 mm apart: the waves from the two gaps cross, and where crest meets crest the screen shows bright lines, while between them, where crest meets trough, the water stays still. The still lines fan out at angles where the paths differ by half a wavelength; switch the view to the intensity to see them.
preset-refraction = Ripple tank: refraction
    .help = Plane waves run onto a glass plate under the water. The water over it is shallower, so the waves slow down and come closer together, and where they cross the plate's slanting edge they bend: Snell's law for water waves.
preset-lens = Ripple tank: a lens
    .help = A lens-shaped glass plate under the water: the waves slow down over it, and the middle of each front spends longest over the plate, so the straight fronts come out curved and meet at a focus behind it, as light does behind a glass lens.
preset-doppler = Ripple tank: a moving source
    .help = A dipper moving across the tank at 0.12 m/s, about 40 % of the waves' speed: ahead of it the crests crowd together, behind it they spread out, as the pitch of a passing siren rises and falls. Raise its speed past the waves' (about 0.31 m/s) and it outruns its own waves: a bow wave.
preset-reflection = Ripple tank: a curved mirror
    .help = Straight waves run into a curved wall shaped like a parabola. Each part of the wall sends them back at its own angle, and all of them meet at one point in front of it, the focus, as light does in a torch's mirror or a satellite dish. Switch the view to the intensity to see the bright focus.
preset-standing = Ripple tank: standing waves
    .help = Straight waves run into a straight wall and come back through themselves. Where they meet they add up to standing waves: lines of still water (nodes) half a wavelength apart, and between them water that goes up and down without going anywhere. Switch the view to the heights and turn the strobe to the dippers' frequency.
preset-phased_array = Ripple tank: a phased array
    .help = Four dippers in a row, 30 mm apart (a little over half a wavelength at 6 Hz), each a quarter of a cycle behind the one before. Their waves add up in one direction only, a beam turned about 25° towards the lagging end: change the phase step and the beam swings round without anything moving, as a phased-array radar or an ultrasound probe steers its beam. Switch the view to the intensity to see the beam.
