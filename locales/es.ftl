# Los textos de wavepool en español, traducidos de locales/en.ftl (Project Fluent,
# https://projectfluent.org/fluent/guide/). Se traduce el texto de cada mensaje, nunca su id
# ni sus { $variables }. Los símbolos de unidades (m/s, Hz, °) y los nombres propios
# se dejan como están.

## Los textos de la propia página (web/*.js)

language = Idioma
controls = Controles
preset = Ajuste predefinido
    .title = Empezar de nuevo con los ajustes y la vista de una lección
preset-choose = elegir…
preset-applied = Ajuste { $name } aplicado.
preset-press-enter = Pulsa Intro para aplicar el ajuste { $name }.
reset = Reiniciar
    .title = Volver al estado inicial de la página: sus parámetros y su vista, agua en calma, los objetos en su sitio
defaults = Valores por defecto
    .title = Poner cada parámetro en su valor por defecto
share-link = Compartir enlace
    .title = Copiar un enlace que abre esta piscina con estos parámetros y esta vista
embed-code = Copiar código para insertar
    .title = Copiar un <iframe> que muestra esta piscina, tal como está ahora, en otra página
link-copied = Enlace copiado.
embed-code-copied = Código para insertar copiado.
embed-title = Piscina de agua interactiva (wavepool)
fullscreen = Pantalla completa
    .title = Pantalla completa (Esc para salir)
play = Reproducir
    .title = Reproducir: el agua y los objetos se ponen en movimiento
pause = Pausa
    .title = Pausa: el agua y los objetos se detienen
on = sí
off = no
dipper = Vibrador { $number }
notice-no-gpu = Este navegador dibuja sin GPU, así que los tamaños más grandes se reducen para que siga respondiendo con fluidez: { $sizes }.
notice-slow-resolution = Aquí los fotogramas tardaban más de un segundo: ahora la resolución es automática.
notice-slow-grid = Aquí los fotogramas tardaban más de un segundo: la malla de simulación se reduce a { $cells } celdas.
fresnel-plot = Reflectancia según el ángulo de incidencia: el modelo de Fresnel elegido sobre la curva exacta
fresnel-angle = ángulo de incidencia
fresnel-caption = Reflectancia: modelo elegido (azul) sobre el exacto (gris); desde el aire, línea continua; desde bajo el agua, discontinua; | tu vista
status-loading = Cargando el agua…
status-device-lost = Se perdió el dispositivo gráfico; reiniciando…
status-waiting = Esperando un contexto de GPU libre: desplaza fuera de la vista otra demo de agua de esta página.
page-intro = Haz clic o arrastra sobre el agua para crear ondas, arrastra un objeto flotante para moverlo y arrastra en otro lugar para girar la cámara; desplaza o pellizca para acercar. Con la demo enfocada: la barra espaciadora pausa, G suelta los objetos, L pone el sol detrás de ti.
page-starting = Iniciando el agua…
page-running = Funciona con { $api }, { $adapter }.
page-running-unnamed = Funciona con { $api } (el navegador no dice qué GPU).
page-failed = El agua no pudo iniciarse aquí: el recuadro de abajo explica por qué.
error-backend-forced = Esta página pidió solo { $api } (backend={ $backend }) y este navegador no pudo iniciarlo:
error-backend-forced-fix = Quita backend={ $backend } de la dirección o de las opciones (o pon backend=auto) para que la demo elija una interfaz que este navegador tenga.
error-no-backend = Este navegador no pudo iniciar la demo de agua: no funcionó ni WebGPU ni WebGL2 (puede que la aceleración gráfica esté desactivada en su configuración).
error-no-webgpu = WebGPU: este navegador no lo ofrece (falta navigator.gpu)
error-stopped = La demo de agua se detuvo: { $reason }
error-device-lost = Se perdió el dispositivo gráfico y no se pudo reiniciar: { $reason }
error-crashed = La demo de agua falló: { $reason }
error-restart = La demo de agua no pudo volver a iniciarse: { $reason }
fallback-picture = Una imagen fija de la piscina (la demo en vivo no pudo iniciarse aquí)
canvas-label = Piscina de agua. Arrastra sobre el agua para crear ondas, arrastra la esfera para moverla, arrastra en otro lugar para girar la cámara. Teclas: flechas giran, + y - acercan, Enter deja caer una gota en el centro, espacio pausa, G gravedad, L luz.
costs-gpu = Tiempo de GPU dibujando el agua: { $times }.
costs-no-gpu-time = Tiempo de GPU: este navegador no lo mide (sin marcas de tiempo de WebGPU).
costs-between = Entre fotogramas: { $times }.
note-flat-under-water = El agua plana es una técnica para mirar desde arriba del agua: bajo el agua dibuja el trazado de rayos.
reading-probe-frequency = Frecuencia de la sonda
reading-probe-swing = Oscilación de la sonda
reading-ruler = Regla
viewer-reset-water = Calmar el agua
    .title = Alisa el agua y devuelve la esfera a su sitio
viewer-frame = fotograma: { $cpu } ms de CPU, { $between } ms entre fotogramas
viewer-gpu = GPU: { $stages }
viewer-gpu-none = Tiempo de GPU: este dispositivo no tiene consultas de marcas de tiempo
viewer-gpu-waiting = Tiempo de GPU: esperando las primeras marcas de tiempo
viewer-costs = dibujar el agua (cáusticas + sombreado): { $costs }
viewer-water = agua: { $cells }² celdas, { $seconds } s simulados
viewer-adapter = adaptador: { $name }
stage-simulation = simulación
stage-caustics = cáusticas
stage-maps = mapas
stage-screen = pantalla
stage-shading = sombreado
stage-the-tank = cubeta
stage-waves = olas
viewer-reset-one = inicial
    .title = Volver al valor predeterminado

## The parameter table and the presets
## (generado por `wavepool messages` a partir de las tablas de src/: edita allí el inglés)

group-water = Agua
group-drops = Gotas
group-light = Luz
group-scene = Escena
group-objects = Objetos
group-tank = Cubeta
group-ambient-waves = Oleaje ambiental
group-optics = Óptica
group-water-colour = Color del agua
group-simulation = Simulación
group-debug = Depuración
group-display = Pantalla
group-flat-water = Agua plana
unit-cells = celdas

## Agua

param-wave_speed = Velocidad de onda
    .help = Velocidad c de las ondas en la ecuación de ondas h_tt = c² ∇²h.
param-damping = Amortiguamiento
    .help = Ritmo k al que las ondas pierden energía (la amplitud decae como exp(-k t / 2)).
param-absorbing_walls = Paredes absorbentes
    .help = Las paredes absorben las ondas en una capa amortiguadora a lo largo de ellas en lugar de reflejarlas.
param-foam = Espuma
    .help = Agua blanca donde las crestas caen más rápido que un cuarto de g, donde el agua sube por una pared y donde las gotas y los cuerpos salpican; se desvanece y se extiende.
param-foam_decay = Vida de la espuma
    .help = Constante de tiempo tau del desvanecimiento de la espuma: tras tau segundos queda un 37 % de ella.

## Gotas

param-drop_radius = Radio de gota
    .help = Radio de la elevación en forma de coseno que añade un clic o un arrastre.
param-drop_strength = Fuerza de gota
    .help = Altura de la elevación en su centro (un valor negativo hunde el agua).
param-start_drops = Gotas al inicio
    .help = Gotas que caen en la piscina al abrir la página, para que sus anillos y las cáusticas que proyectan se vean de inmediato (0: el agua empieza en calma).

## Luz

param-sun_azimuth = Acimut del sol
    .help = Dirección del sol en la brújula, alrededor de la piscina.
param-sun_elevation = Altura del sol
    .help = Altura del sol sobre el horizonte.
param-sun_size = Tamaño del sol
    .help = Diámetro angular del disco solar en el cielo y en sus reflejos (el sol real: 0,5°).
param-exposure = Exposición
    .help = Brillo de la imagen en pasos fotográficos (cada +1 duplica la luz antes de la curva tonal fílmica), además de la exposición propia de la cámara: con el sol más bajo se compensa la luz que se pierde.
param-setting = Entorno
    .help = Dónde está la piscina: hundida en una terraza pavimentada bajo el cielo, o la caja en corte del clásico, abierta por las paredes cercanas para ver la sección del agua.
param-setting-deck = terraza
param-setting-cutaway = en corte
param-caustics = Cáusticas
    .help = Luz que las ondas concentran sobre el fondo, las paredes y la esfera.
param-caustic_contrast = Contraste de las cáusticas
    .help = Cuánto destacan las líneas cáusticas: la luz concentrada elevada a esta potencia. 1 es la luz que concentran las ondas simuladas, tal como la guarda el mapa de cáusticas (difuminada sobre sus téxeles, así que las líneas son más anchas y tenues de lo que las dibujaría el sol); 2 les devuelve el brillo de la red de una piscina al sol.
param-tile_gloss = Brillo de los azulejos
    .help = Cuánto refleja el esmalte de los azulejos: 1, un esmalte cerámico (el cielo y el destello del sol en los azulejos por encima del agua, sobre todo en sus bordes redondeados); 0, azulejos mates.

## Escena

param-scene = Escena
    .help = La piscina, el mar abierto hasta el horizonte bajo el mismo cielo, o la cubeta de ondas del laboratorio escolar con su lámpara y su pantalla.
param-scene-pool = piscina
param-scene-sea = mar
param-scene-tank = cubeta
param-sea_wind = Viento
    .help = Velocidad del viento sobre el mar: un viento más fuerte lleva la energía de las olas a longitudes de onda mayores.
param-sea_wind_direction = Dirección del viento
    .help = Dirección hacia la que sopla el viento, de +x hacia +z.
param-sea_wave_height = Altura de ola
    .help = Altura significativa de ola: cuatro desviaciones típicas de la altura del mar (aproximadamente la media del tercio de olas más altas).
param-sea_choppiness = Encrespamiento
    .help = Cuánto se desplaza el agua hacia los lados, hacia las crestas, afilándolas (la lambda de Tessendorf).
param-sea_fog = Niebla
    .help = Bruma sobre el mar que se aclara con la altura y lleva el agua y el cielo a un mismo color en el horizonte.
param-sea_fog_distance = Distancia de la niebla
    .help = Distancia en la que la bruma a nivel del mar atenúa la luz hasta un 37 %.
param-sea_island = Isla
    .help = Una isla con playas, vista a través de los bajíos que la rodean, donde las olas hacen espuma a lo largo de la orilla: mar adentro, en la bruma, o en la costa, con sus bajíos bajo la zona donde los clics crean ondas y las cáusticas de esas ondas iluminan la arena.
param-sea_island-none = ninguna
param-sea_island-offshore = mar adentro
param-sea_island-shore = costa
param-sea_grid = Mostrar la malla
    .help = Dibuja el contorno de las celdas de la malla sobre la que se dibuja el mar: se coloca sobre la pantalla y se proyecta sobre el agua, así que sus celdas tienen en pantalla un tamaño parecido, pequeñas cerca de ti y alargadas hacia el horizonte.

## Objetos

param-sea_objects = Objetos
    .help = Lo que flota en el mar: la esfera, el pato y la pelota de playa de la piscina, tantas veces más grandes como la zona de agua simulada lo es respecto a la piscina. Se mecen con las olas y dejan estelas en esa zona.
param-sea_objects-none = ninguno
param-sea_objects-sphere = esfera
param-sea_objects-duck = pato
param-sea_objects-both = ambos
param-sea_objects-ball = pelota
param-sea_objects-all = todos
param-objects = Objetos
    .help = Lo que flota en la piscina: cualquiera de estos, la esfera, un pato de goma y una pelota de playa (en lista, p. ej. esfera,pato), todos o ninguno.
param-objects-none = ninguno
param-objects-sphere = esfera
param-objects-duck = pato
param-objects-both = ambos
param-objects-ball = pelota
param-objects-all = todos
param-sphere_radius = Radio de la esfera
    .help = Radio de la esfera.
param-sphere_density = Densidad de la esfera
    .help = Masa por unidad de volumen; por debajo de los 1000 kg/m³ del agua, la esfera flota.
param-duck_density = Densidad del pato
    .help = Masa por unidad de volumen del pato de goma: cuanto más ligero, más alto flota.
param-ball_radius = Radio de la pelota
    .help = Radio de la pelota de playa.
param-ball_density = Densidad de la pelota
    .help = Masa por unidad de volumen de la pelota de playa (aire en una capa fina, con arena dentro para que oscile menos): ligera, así que flota alta sobre el agua.
param-gravity = Gravedad
    .help = Deja que los objetos caigan, floten, oscilen y vayan a la deriva sobre las ondas (tecla G); desactivada, se quedan donde se colocan.

## Cubeta

param-tank_setup = Montaje
    .help = Qué hay en la cubeta: un vibrador, dos vibradores, una barra recta que produce ondas planas, la barra tras una barrera con una o dos rendijas, la barra y una placa de vidrio cuyo borde recto desvía las ondas (refracción), una placa en forma de lente que las lleva a un foco, un vibrador que se mueve por la cubeta (Doppler), una pared curva que refleja las ondas de la barra hacia un foco (un espejo parabólico), una pared recta frente a la barra (ondas estacionarias) o un prisma de vidrio que desvía las ondas de la barra.
param-tank_setup-dipper = vibrador
param-tank_setup-two_dippers = dos vibradores
param-tank_setup-plane_wave = onda plana
param-tank_setup-single_slit = una rendija
param-tank_setup-double_slit = doble rendija
param-tank_setup-refraction = refracción
param-tank_setup-lens = lente
param-tank_setup-doppler = doppler
param-tank_setup-reflection = reflexión
param-tank_setup-standing = estacionarias
param-tank_setup-prism = prisma
param-tank_look = Aspecto
    .help = La vista pantalla muestra desde arriba el papel bajo la cubeta, como lo ve la clase; aparato muestra en 3D la cubeta del laboratorio: la lámpara sobre la bandeja, el agua, su marco sobre sus patas y el papel en la mesa de debajo con la imagen de la lámpara (arrastra para rodearla); dividida muestra las dos una junto a otra.
param-tank_look-screen = pantalla
param-tank_look-apparatus = aparato
param-tank_look-split = dividida
param-tank_view = Vista
    .help = Lo que muestra la imagen: la luz de la lámpara en la pantalla bajo la cubeta (cada cresta la concentra como una lente en una línea brillante), la altura del agua como color, o la intensidad: la altura al cuadrado, promediada aproximadamente durante el último segundo.
param-tank_view-screen = pantalla
param-tank_view-heights = alturas
param-tank_view-intensity = intensidad
param-tank_tool = Puntero
    .help = Qué hace un clic o un arrastre sobre la bandeja: soltar pequeños pulsos en el agua, trazar paredes rectas que las ondas no pueden atravesar, desde donde pulsas hasta donde sueltas (una barrera propia, un reflector, una caja), borrar para volver a dejar agua libre, colocar la sonda donde haces clic, poner una regla desde donde pulsas hasta donde sueltas (su longitud aparece bajo la cubeta: colócala a lo largo de diez crestas para medir una longitud de onda), o mover un vibrador o la barra: pulsa sobre él y arrastra (el vibrador que pulses muestra entonces su propia frecuencia, amplitud y fase).
param-tank_tool-drops = gotas
param-tank_tool-walls = paredes
param-tank_tool-erase = borrar
param-tank_tool-probe = sonda
param-tank_tool-ruler = regla
param-tank_tool-move = mover
param-tank_frequency = Frecuencia
    .help = Cuántas veces suben y bajan los vibradores (o la barra). La longitud de onda es la velocidad dividida entre la frecuencia.
param-tank_amplitude = Amplitud
    .help = Cuánto suben y bajan el agua los vibradores. Basta una fracción de milímetro: así cada cresta concentra la luz de la lámpara cerca de la pantalla, como en una cubeta de laboratorio bien ajustada; con ondas más altas la luz se concentra por encima de la pantalla y las líneas se deshacen en ella.
param-tank_dippers = Vibradores
    .help = Cuántos vibradores hay en fila en el montaje de dos vibradores, separados por la distancia entre rendijas.
param-tank_phase = Paso de fase
    .help = Cuánto se retrasa cada vibrador de la fila respecto a su vecino (un ciclo completo son 360°). Las ondas se suman donde el camino compensa el retraso: el haz gira hacia el extremo retrasado, según sin θ = (paso/360°) λ / separación. Así orienta su haz, sin moverse, un radar de antenas en fase o una sonda de ecografía.
param-tank_detune = Desintonía
    .help = Cuánto más rápido va cada vibrador de la fila que el anterior. Dos vibradores producen entonces pulsaciones: donde sus ondas se encontraban cresta con cresta pronto se encuentran cresta con valle, y las líneas en reposo barren la bandeja tantas veces por segundo; una fila de cuatro hace girar su haz.
param-tank_amplitude_ratio = Razón de amplitudes
    .help = Cuánto mueve el agua cada vibrador de la fila, como fracción del anterior. Con dos vibradores de distinta intensidad, las líneas en reposo ya no están quietas: donde una cresta se encuentra con un valle, las ondas solo se anulan en parte.
param-tank_depth = Profundidad del agua
    .help = La profundidad del agua. Aquí las ondas avanzan a la velocidad de aguas someras sqrt(g d), más rápido en agua más profunda; sobre una placa de vidrio el agua es menos profunda, así que allí las ondas se frenan y se desvían. (Las ondas de un centímetro de una cubeta real no son largas frente a la profundidad y también las mueve la tensión superficial, así que van más despacio y su velocidad depende de la longitud de onda; estas no. Cada lección usa una sola frecuencia y lo que muestra depende solo de las longitudes de onda, así que sigue siendo válido).
param-tank_size = Tamaño de la bandeja
    .help = El lado de la bandeja cuadrada.
param-tank_slit_width = Anchura de rendija
    .help = La anchura de cada abertura de la barrera.
param-tank_slit_spacing = Separación de rendijas
    .help = La distancia entre los centros de las dos rendijas, o de los dos vibradores.
param-tank_lamp_height = Altura de la lámpara
    .help = La altura de la lámpara sobre el agua. La pantalla está 0,5 m por debajo de la bandeja; con la lámpara más baja, la imagen se ensancha.
param-tank_source_speed = Velocidad del vibrador
    .help = A qué velocidad cruza la cubeta el vibrador del montaje Doppler. Por delante, las ondas se apiñan; por detrás, se separan; si va más rápido que las ondas (unos 0,31 m/s en 10 mm de agua), deja una onda de proa, una V como detrás de un barco.
param-tank_strobe = Estroboscopio
    .help = Ilumina la cubeta con destellos tantas veces por segundo (0: lámpara fija). A la frecuencia de los vibradores, cada destello encuentra las ondas en el mismo sitio, así que el patrón se queda quieto y se puede medir; un poco por encima o por debajo, las ondas avanzan o retroceden lentamente.
param-tank_lines = Líneas de rendija
    .help = Dibuja, desde entre las rendijas, las direcciones donde la teoría sitúa el patrón: con dos rendijas, las líneas brillantes, d sin θ = m λ (d, la separación entre rendijas); con una rendija, las oscuras, w sin θ = m λ (w, su anchura).
param-tank_beaches = Playas
    .help = Playas inclinadas a lo largo de las paredes que absorben las ondas (como las tiras de espuma o de malla de una cubeta real), o paredes desnudas que las reflejan.
param-tank_pulse = Pulso único
    .help = Los vibradores (o la barra) hacen una sola cresta y se detienen, cada vez que se activa esta opción o se reinicia la cubeta, en lugar de un tren continuo de ondas: observa cómo una sola onda se propaga, se refleja y atraviesa las rendijas. Todos los vibradores levantan el agua a la vez (el paso de fase, la desintonía o la fase o frecuencia propias de un vibrador no dan forma al pulso).
param-tank_probe = Sonda
    .help = Una sonda en el agua (el anillo) y la gráfica de su altura durante los últimos cuatro segundos en la esquina de la imagen; bajo la cubeta, la frecuencia y la oscilación que mide. Colócala con la herramienta sonda del Puntero o con los dos deslizadores de abajo.
param-tank_probe_x = Sonda a lo ancho
    .help = La posición de la sonda a lo ancho de la bandeja, desde el centro, hacia la derecha vista desde arriba con la barra abajo (siempre dentro de la bandeja).
param-tank_probe_z = Sonda a lo largo
    .help = La posición de la sonda a lo largo de la bandeja, desde el centro hacia el lado opuesto (siempre dentro de la bandeja).
param-tank_graph = Gráfica de intensidad
    .help = Una línea que cruza la bandeja y, sobre ella, la gráfica de la intensidad a lo largo de la línea (la altura al cuadrado, promediada aproximadamente durante el último segundo): dónde se suman las ondas y dónde se anulan, como se vería en una pantalla lejos de las rendijas.
param-tank_graph_z = Línea de la gráfica
    .help = Dónde cruza la bandeja la línea de la gráfica de intensidad, desde el centro hacia el lado opuesto (siempre dentro de la bandeja).

## Oleaje ambiental

param-ambient = Oleaje ambiental
    .help = Una superficie que se mueve por sí sola bajo tus ondas: ninguno, una suma de senos viajeros de cresta aguda, las ondas estacionarias propias de la piscina (modos), que llegan planas a cada pared, ondas de Gerstner (el agua se mueve en círculos y las crestas se afilan) o un océano FFT (miles de ondas a partir de un espectro).
param-ambient-none = ninguno
param-ambient-sines = senos
param-ambient-modes = modos
param-ambient-gerstner = gerstner
param-ambient-fft = fft
param-wind_speed = Velocidad del viento
    .help = Viento del espectro de Phillips del que salen las amplitudes de las ondas: un viento más fuerte da más altura a las ondas más largas.
param-wind_direction = Dirección del viento
    .help = Dirección hacia la que sopla el viento, de +x hacia +z.
param-wave_height = Altura de ola
    .help = Altura significativa H_s del oleaje ambiental: cuatro veces la desviación típica de la superficie.
param-wave_spread = Dispersión de direcciones
    .help = Cuánto (±) se apartan las direcciones de las ondas viajeras de la del viento.
param-steepness = Pendiente Q
    .help = Pendiente de Gerstner: 0 da senos simples; hacia 1 el agua se acumula bajo crestas agudas (en 1 se convertirían en picos).
param-spectrum = Espectro
    .help = El espectro de ondas del océano FFT: phillips (el de Tessendorf) o jonswap (mares medidos con fetch limitado, un pico más agudo; aquí, un fetch de 100 m).
param-spectrum-phillips = phillips
param-spectrum-jonswap = jonswap
param-fft_size = Malla FFT
    .help = Ondas por lado de la red del océano FFT: con 128 se añaden ondulaciones de hasta 6 cm.
param-choppiness = Encrespamiento
    .help = El agua del océano FFT también se mueve hacia los lados y se acumula bajo las crestas (las olas encrespadas de Tessendorf); 0 es solo el campo de alturas.

## Óptica

param-fresnel = Modelo de Fresnel
    .help = Cuánta luz refleja la superficie en cada ángulo: las ecuaciones de Fresnel exactas, las mismas a partir de una textura de consulta, la aproximación de Schlick, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) o 1-cos θ.
param-fresnel-exact = exacto
param-fresnel-table = tabla
param-fresnel-schlick = schlick
param-fresnel-inverse_power = potencia inversa
param-fresnel-clamped_power = potencia acotada
param-fresnel-linear = lineal
param-specular = Brillo del sol
    .help = Forma del destello del sol en el agua: phong (rayo reflejado frente al sol) o blinn-phong (normal frente al vector intermedio), más ancho con el mismo brillo especular.
param-specular-phong = phong
param-specular-blinn_phong = blinn-phong
param-shininess = Brillo especular
    .help = Exponente s del cos^s del brillo: cuanto más alto, más pequeño y nítido es el destello.
param-dispersion = Dispersión
    .help = La luz roja y la azul se desvían cada una según su índice de refracción (agua: 1,331 rojo, 1,335 verde, 1,337 azul), con esta cantidad de veces la separación real: franjas de color en los bordes de las cáusticas y en el borde de la ventana de Snell. 0: desactivada.

## Color del agua

param-absorption_red = Absorción, rojo
    .help = Absorción de Beer-Lambert de la luz roja por metro de agua: tras d metros queda exp(-a d) de ella.
param-absorption_green = Absorción, verde
    .help = Absorción de Beer-Lambert de la luz verde por metro de agua: tras d metros queda exp(-a d) de ella.
param-absorption_blue = Absorción, azul
    .help = Absorción de Beer-Lambert de la luz azul por metro de agua: tras d metros queda exp(-a d) de ella.
param-scatter_red = Luz dispersada, rojo
    .help = Luz que la propia agua dispersa hacia ti (rojo, en unidades lineales; el cielo está en torno a 0,5): compensa lo que quita la absorción, así que el agua profunda toma este color en vez de volverse negra. 0 en todos los canales: desactivada.
param-scatter_green = Luz dispersada, verde
    .help = Luz que la propia agua dispersa hacia ti (verde, en unidades lineales; el cielo está en torno a 0,5): compensa lo que quita la absorción, así que el agua profunda toma este color en vez de volverse negra. 0 en todos los canales: desactivada.
param-scatter_blue = Luz dispersada, azul
    .help = Luz que la propia agua dispersa hacia ti (azul, en unidades lineales; el cielo está en torno a 0,5): compensa lo que quita la absorción, así que el agua profunda toma este color en vez de volverse negra. 0 en todos los canales: desactivada.
param-view_colour = Color según la vista
    .help = La luz dispersada pierde la mitad de su verde en las trayectorias rasantes y la conserva al mirar hacia abajo, como los videojuegos tiñen el agua según el ángulo de vista (requiere luz dispersada).

## Simulación

param-sim_size = Resolución de la malla
    .help = Celdas por lado de la malla de simulación; al cambiarla, el agua se remuestrea, no se reinicia.
param-paused = En pausa
    .help = Congela el agua (barra espaciadora).

## Depuración

param-debug_view = Vista de depuración
    .help = Muestra una de las texturas de la simulación: altura (rojo arriba, azul abajo), normales de la superficie, velocidad vertical o el mapa de cáusticas; o la reflectancia de Fresnel del agua en gris (negro 0, blanco 1); o el espectro del oleaje ambiental (amplitud por vector de onda, escala logarítmica, k = 0 en el centro, anillos en las longitudes de onda de 0,9 m y 0,2 m).
param-debug_view-off = ninguna
param-debug_view-height = altura
param-debug_view-normals = normales
param-debug_view-velocity = velocidad
param-debug_view-caustics = cáusticas
param-debug_view-reflectance = reflectancia
param-debug_view-spectrum = espectro
param-debug_inset = Depuración en recuadro
    .help = Muestra la vista de depuración en una esquina de la escena (activada) o sobre toda ella (desactivada).

## Pantalla

param-quality = Resolución
    .help = Escala de la resolución de la escena: fija, o automática (baja por pasos hasta el 50% mientras los fotogramas tarden más que el presupuesto por fotograma, y vuelve a subir cuando hay margen).
param-quality-auto = automática
param-frame_budget = Presupuesto por fotograma
    .help = Tiempo máximo que debería tardar un fotograma; con la resolución automática, los fotogramas más lentos bajan la resolución.

## Agua plana

param-render_mode = Dibujo del agua
    .help = Cómo se dibuja la superficie del agua. rayos: cada píxel de la superficie traza sus rayos reflejado y refractado a través de la piscina. plana: la técnica de los videojuegos: la escena se dibuja dos veces más en texturas, reflejada en el plano del agua (reflexión) y recortada bajo él (refracción), y un plano liso mezcla las dos según Fresnel, ondulado por una distorsión en lugar de desviado por las ondas. Es una técnica para ver desde fuera del agua: bajo el agua dibuja el trazador de rayos. dividida: plana a la izquierda y con trazado de rayos a la derecha de un divisor que puedes arrastrar.
param-render_mode-raytraced = rayos
param-render_mode-flat = plana
param-render_mode-split = dividida
param-split = Divisor
    .help = Dónde está el divisor, como fracción del ancho desde la izquierda: agua plana a su izquierda, trazado de rayos a su derecha. Arrastra el divisor sobre el lienzo para moverlo.
param-flat_distortion = Distorsión
    .help = Lo que ondula el reflejo y la refracción del agua plana: dudv, un mapa de distorsión en mosaico (un mapa dUdV) que se desplaza con el tiempo (los clics no crean ondas en él), u ondulaciones, las pendientes de la propia simulación (las mismas ondas que el trazador de rayos, con una óptica simulada).
param-flat_distortion-dudv = dudv
param-flat_distortion-ripples = ondulaciones
param-flat_strength = Intensidad de distorsión
    .help = Cuánto desplaza la distorsión las texturas de reflexión y refracción, como fracción de la pantalla. No crece con la distancia a lo que se ve, como sí hace la refracción real: un borde muy por encima del agua ondula tanto como los azulejos bajo ella.
param-dudv_speed = Velocidad de distorsión
    .help = Mosaicos del mapa dudv desplazados por segundo simulado (se detiene cuando el agua está en pausa); con la distorsión dudv.
param-flat_resolution = Resolución de textura
    .help = Tamaño de las texturas de reflexión y refracción respecto al de la escena: más pequeño es más barato y más borroso.
param-flat_caustics = Cáusticas
    .help = Luz sobre la piscina bajo el agua plana: desactivadas (las de una superficie en calma), falsas (un brillo donde la normal de la distorsión enviaría el sol en vertical hacia abajo; sin concentración, sin pasada extra) o reales (el mapa de cáusticas del trazador de rayos, una pasada más).
param-flat_caustics-off = desactivadas
param-flat_caustics-fake = falsas
param-flat_caustics-real = reales
param-flat_soft_edge = Borde suave
    .help = El agua menos profunda que esto (en la dirección de la vista) se distorsiona menos, lo que oculta la junta donde el plano liso se encuentra con las paredes; 0 muestra la junta.

## Ajustes propios de cada vibrador de la cubeta (título del grupo: «Vibrador» y su número)

param-frequency = Su frecuencia
    .help = Cuántas veces sube y baja este vibrador. Dos vibradores con frecuencias un poco distintas producen pulsaciones: sus líneas en reposo barren la bandeja.
param-amplitude = Su amplitud
    .help = Cuánto mueve el agua este vibrador (0 lo detiene). Donde las ondas de un vibrador fuerte y uno débil se encuentran cresta con valle, solo se anulan en parte.
param-phase = Su fase
    .help = Cuánto se adelanta este vibrador a la fase fijada (un ciclo completo son 360°; negativo: se retrasa). Dos vibradores desfasados 180° envían cresta contra valle: la línea central entre ellos queda en reposo.

## Ajustes predefinidos (el nombre y lo que lee el estudiante)

preset-classic = El aspecto clásico
    .help = Una esfera que se queda donde se coloca (G la deja caer), paredes que reflejan, cáusticas: la piscina tal como la muestra el clásico WebGL Water.
preset-calm = Agua en calma
    .help = Nada en la piscina, gotas pequeñas, ondas que se extinguen rápido en paredes absorbentes: una superficie tranquila para estudiar las ondas de una en una.
preset-busy = Una piscina animada
    .help = La esfera y el pato flotando sobre un agua rápida y viva, con gotas grandes y paredes que reflejan.
preset-fresnel = Lección: reflectancia de Fresnel
    .help = Agua tranquila y vacía vista de forma rasante a lo largo de la piscina, de modo que el ángulo de incidencia va de unos 50° cerca de ti a rasante en el lado opuesto: cambia el modelo de Fresnel y observa cómo cambian el reflejo y la gráfica.
preset-glint = Lección: el destello del sol
    .help = Mirando hacia un sol bajo: arrastra sobre el agua para crear ondas y ver el destello de Blinn-Phong alargado en la dirección de la vista; cambia el Brillo del sol a phong y modifica el brillo especular para comparar.
preset-breeze = Lección: oleaje ambiental
    .help = Una brisa ligera hace que ondas de cresta aguda recorran la piscina bajo tus ondas; cambia Oleaje ambiental a modos para ver las ondas estacionarias propias de la piscina, que llegan planas a cada pared, a gerstner para ver el agua moverse en círculos, o a fft para un espectro de miles de ondas (la vista de depuración espectro muestra las ondas de cada modelo).
preset-ocean = Lección: un océano FFT
    .help = El océano de Tessendorf en la piscina: un espectro de Phillips de unas mil ondas en una red de 128 puntos, sumadas con una FFT en cada fotograma; la vista de depuración muestra el espectro, a sotavento de la dirección del viento.
preset-flat = Lección: agua plana frente a trazado de rayos
    .help = El agua plana de los videojuegos (izquierda) frente al trazador de rayos (derecha), con la esfera medio fuera del agua: arrastra el divisor sobre la esfera. A la izquierda, su mitad sumergida se ve sin desviar a su profundidad real y los reflejos ondulan con un desplazamiento fijo; a la derecha, el agua la eleva y lo desvía todo según las pendientes de las ondas. Crea ondas y cambia la distorsión a ondulaciones para ver las mismas ondas con una óptica simulada.
preset-lake = Lección: el color del agua
    .help = Agua verde de lago: absorbe el rojo, el verde y el azul más deprisa que la de la piscina y dispersa una luz verdeazulada propia, así que la parte honda se vuelve verde en vez de oscura (pon la luz dispersada a 0 para ver solo Beer-Lambert).
preset-noon = Mediodía
    .help = El sol casi en el cenit: un cielo azul intenso, sombras cortas, las cáusticas más brillantes en el fondo.
preset-evening = Atardecer
    .help = Un sol bajo y cálido de lado, con la imagen expuesta para él: sombras largas sobre la terraza, el agua oscura donde el borde le da sombra, la pared del fondo iluminada por las cáusticas del sol.
preset-sea = Lección: el mar abierto
    .help = Mar abierto hasta el horizonte con una brisa moderada: cinco cascadas FFT con mosaicos de distintos tamaños, para que ningún patrón se repita; la malla sobre la que se dibuja el mar se proyecta desde la pantalla, así que su detalle sigue a tu vista; la bruma lleva el mar y el cielo a un mismo color en el horizonte (desactiva Niebla para ver el borde del mar); la isla de enfrente se alza en bajíos turquesa con espuma a lo largo de la orilla y se refleja en el agua (activa Mostrar la malla para ver la malla). Haz clic cerca del centro para crear ondas en la zona de agua simulada y observa cómo se alejan; el pato de goma que hay allí, tantas veces más grande como la zona lo es respecto a la piscina, se mece con las olas y deja estela: arrástralo para verla.
preset-shore = Lección: ondas en los bajíos
    .help = La playa de la isla junto a la zona de agua simulada, con una brisa ligera y el sol alto: las pendientes de las olas concentran la luz del sol en una red de cáusticas sobre la arena, unos metros más abajo. Haz clic en el agua para crear ondas: donde la profundidad es la adecuada, sus anillos se concentran en líneas brillantes en el fondo, que las muestran mucho mejor que la propia superficie. El balanceo del pato dibuja sus propios anillos, y su sombra cae sobre la arena.
preset-dawn = Un mar en calma al amanecer
    .help = Un sol bajo de frente sobre un mar en calma: su destello se extiende en un largo camino de reflejos sobre las olas pequeñas, con el cielo cálido a lo largo del horizonte.
preset-storm = Una tormenta en el mar
    .help = Un viento fuerte levanta olas de 5 m con crestas afiladas bajo un sol bajo, entre una bruma espesa; el pato es zarandeado entre las cabrillas.
preset-tank = Cubeta de ondas: un vibrador
    .help = Una cubeta de ondas escolar vista desde arriba: un vibrador oscila diez veces por segundo en el centro de una bandeja con 10 mm de agua, y la lámpara sobre la cubeta proyecta sus anillos en la pantalla de abajo como círculos brillantes, porque cada cresta concentra la luz como una lente. Cambia la vista a alturas para ver las propias ondas; cambia la frecuencia y observa cómo los anillos se apiñan (la longitud de onda es la velocidad dividida entre la frecuencia).
preset-single_slit = Cubeta de ondas: una rendija
    .help = Una barra recta produce ondas planas que llegan a una barrera con una abertura. Tras la abertura se abren en abanico; cuanto más estrecha es la abertura frente a la longitud de onda, más ancho es el abanico (prueba a cambiar la anchura de rendija).
preset-double_slit = Cubeta de ondas: doble rendija
    .help = Ondas planas que pasan por dos aberturas separadas 90 mm: las ondas de las dos aberturas se cruzan, y donde una cresta se encuentra con otra cresta la pantalla muestra líneas brillantes, mientras que entre ellas, donde una cresta se encuentra con un valle, el agua queda en reposo. Las líneas en reposo se abren en abanico en los ángulos en que los caminos difieren en media longitud de onda; cambia la vista a intensidad para verlas.
preset-refraction = Cubeta de ondas: refracción
    .help = Ondas planas llegan a una placa de vidrio bajo el agua. Sobre ella el agua es menos profunda, así que las ondas se frenan y se acercan entre sí, y donde cruzan el borde inclinado de la placa se desvían: la ley de Snell para las ondas en el agua.
preset-lens = Cubeta de ondas: una lente
    .help = Una placa de vidrio en forma de lente bajo el agua: las ondas se frenan sobre ella, y el centro de cada frente es el que más tiempo pasa sobre la placa, así que los frentes rectos salen curvados y se juntan en un foco detrás de ella, como hace la luz detrás de una lente de vidrio.
preset-doppler = Cubeta de ondas: una fuente en movimiento
    .help = Un vibrador que cruza la cubeta a 0,12 m/s, un 40 % de la velocidad de las ondas: por delante las crestas se apiñan y por detrás se separan, igual que el tono de una sirena que pasa sube y baja. Sube su velocidad por encima de la de las ondas (unos 0,31 m/s) y dejará atrás sus propias ondas: una onda de proa.
preset-reflection = Cubeta de ondas: un espejo curvo
    .help = Ondas rectas llegan a una pared curva con forma de parábola. Cada parte de la pared las devuelve con su propio ángulo, y todas se juntan en un punto delante de ella, el foco, como hace la luz en el espejo de una linterna o en una antena parabólica. Cambia la vista a intensidad para ver el foco brillante.
preset-standing = Cubeta de ondas: ondas estacionarias
    .help = Ondas rectas llegan a una pared recta y vuelven atravesándose a sí mismas. Donde se encuentran se suman en ondas estacionarias: líneas de agua en reposo (nodos) separadas media longitud de onda, y entre ellas agua que sube y baja sin desplazarse. Cambia la vista a alturas y pon el estroboscopio a la frecuencia de los vibradores.
preset-phased_array = Cubeta de ondas: antenas en fase
    .help = Cuatro vibradores en fila, separados 30 mm (algo más de media longitud de onda a 6 Hz), cada uno un cuarto de ciclo por detrás del anterior. Sus ondas se suman en una sola dirección, un haz girado unos 25° hacia el extremo retrasado: cambia el paso de fase y el haz gira sin que nada se mueva, como orienta su haz un radar de antenas en fase o una sonda de ecografía. Cambia la vista a intensidad para ver el haz.
