# Die Texte von wavepool auf Deutsch, übersetzt aus locales/en.ftl (Project Fluent,
# https://projectfluent.org/fluent/guide/). Eine Sprache kommt hinzu, indem man en.ftl nach
# locales/<tag>.ftl kopiert, den Text jeder Nachricht übersetzt (nie ihre ID oder ihre { $variables }) und
# den Tag in web/i18n.js (LANGUAGES) einträgt. Einheitenzeichen (m/s, Hz, °) und Eigennamen
# bleiben, wie sie sind.

## Die eigenen Texte der Seite (web/*.js)

language = Sprache
controls = Steuerung
preset = Vorlage
    .title = Neu beginnen mit den Einstellungen und der Ansicht einer Lektion
preset-choose = auswählen…
preset-applied = Vorlage { $name } angewendet.
preset-press-enter = Enter drücken, um die Vorlage { $name } anzuwenden.
reset = Zurücksetzen
    .title = Zurück zum Zustand beim Laden der Seite: ihre Parameter und Ansicht, ruhiges Wasser, die Objekte an ihrem Platz
defaults = Standard
    .title = Alle Parameter auf ihren Standardwert setzen
share-link = Link teilen
    .title = Einen Link kopieren, der dieses Becken mit diesen Parametern und dieser Ansicht öffnet
embed-code = Embed-Code kopieren
    .title = Ein <iframe> kopieren, das dieses Becken so, wie es jetzt ist, in einer anderen Seite zeigt
link-copied = Link kopiert.
embed-code-copied = Embed-Code kopiert.
embed-title = Interaktives Wasserbecken (wavepool)
fullscreen = Vollbild
    .title = Vollbild (Esc beendet es)
play = Start
    .title = Start: Wasser und Gegenstände setzen sich in Bewegung
pause = Pause
    .title = Pause: Wasser und Gegenstände halten an
on = an
off = aus
dipper = Erreger { $number }
notice-no-gpu = Dieser Browser zeichnet ohne GPU, daher sind die größten Stufen verkleinert, damit alles flüssig bleibt: { $sizes }.
notice-slow-resolution = Bilder dauerten hier über eine Sekunde: Die Auflösung ist jetzt automatisch.
notice-slow-grid = Bilder dauerten hier über eine Sekunde: Das Simulationsgitter ist auf { $cells } Zellen verkleinert.
fresnel-plot = Reflexionsgrad über dem Einfallswinkel: das gewählte Fresnel-Modell über der exakten Kurve
fresnel-angle = Einfallswinkel
fresnel-caption = Reflexionsgrad: gewähltes Modell (blau) über exakt (grau); aus Luft durchgezogen, von unter Wasser gestrichelt; | dein Blick
status-loading = Das Wasser lädt…
status-device-lost = Das Grafikgerät ging verloren; Neustart…
status-waiting = Warte auf einen freien GPU-Kontext: Scrollen Sie eine andere Wasser-Demo auf dieser Seite aus dem Bild.
page-intro = Klicken oder ziehen Sie auf dem Wasser, um Wellen zu erzeugen, ziehen Sie einen schwimmenden Gegenstand, um ihn zu verschieben, und ziehen Sie anderswo, um die Kamera zu drehen; scrollen oder mit zwei Fingern zoomen. Wenn die Demo den Fokus hat: Leertaste hält an, G lässt die Gegenstände fallen, L stellt die Sonne hinter Sie.
page-starting = Das Wasser startet…
page-running = Läuft mit { $api }, { $adapter }.
page-running-unnamed = Läuft mit { $api } (der Browser verrät nicht, welche GPU).
page-failed = Das Wasser konnte hier nicht starten: Der Kasten unten sagt, warum.
error-backend-forced = Diese Seite verlangte nur { $api } (backend={ $backend }), und dieser Browser konnte es nicht starten:
error-backend-forced-fix = Entfernen Sie backend={ $backend } aus der Adresse oder den Optionen (oder setzen Sie backend=auto), damit die Demo eine Schnittstelle wählt, die dieser Browser hat.
error-no-backend = Dieser Browser konnte die Wasser-Demo nicht starten: Weder WebGPU noch WebGL2 funktionierten (die Grafikbeschleunigung ist in seinen Einstellungen vielleicht ausgeschaltet).
error-no-webgpu = WebGPU: Dieser Browser bietet es nicht an (navigator.gpu fehlt)
error-stopped = Die Wasser-Demo hat angehalten: { $reason }
error-device-lost = Das Grafikgerät ging verloren und konnte nicht neu gestartet werden: { $reason }
error-crashed = Die Wasser-Demo ist abgestürzt: { $reason }
error-restart = Die Wasser-Demo konnte nicht wieder starten: { $reason }
fallback-picture = Ein Standbild des Wasserbeckens (die Live-Demo konnte hier nicht starten)
canvas-label = Wasserbecken. Auf dem Wasser ziehen macht Wellen, die Kugel ziehen verschiebt sie, anderswo ziehen dreht die Kamera. Tasten: Pfeile drehen, + und - zoomen, Enter lässt einen Tropfen in die Mitte fallen, Leertaste hält an, G Schwerkraft, L Licht.
costs-gpu = GPU-Zeit für das Wasser: { $times }.
costs-no-gpu-time = GPU-Zeit: Dieser Browser misst sie nicht (keine WebGPU-Zeitstempel).
costs-between = Zwischen den Bildern: { $times }.
note-flat-under-water = Ebenes Wasser ist eine Technik für den Blick von oben: Unter Wasser zeichnet das Raytracing.
reading-probe-frequency = Frequenz der Sonde
reading-probe-swing = Ausschlag der Sonde
reading-ruler = Lineal
viewer-reset-water = Wasser glätten
    .title = Das Wasser glätten und die Kugel zurücklegen
viewer-frame = Bild: { $cpu } ms CPU, { $between } ms zwischen Bildern
viewer-gpu = GPU: { $stages }
viewer-gpu-none = GPU-Zeit: Dieses Gerät hat keine Zeitstempel-Abfragen
viewer-gpu-waiting = GPU-Zeit: Warte auf die ersten Zeitstempel
viewer-costs = Wasser zeichnen (Kaustiken + Schattierung): { $costs }
viewer-water = Wasser: { $cells }² Zellen, { $seconds } s simuliert
viewer-adapter = Adapter: { $name }
stage-simulation = Simulation
stage-caustics = Kaustiken
stage-maps = Karten
stage-screen = Schirm
stage-shading = Schattierung
stage-the-tank = Wanne
stage-waves = Wellen
viewer-reset-one = zurück
    .title = Auf den Standardwert zurücksetzen

## The parameter table and the presets
## (von `wavepool messages` aus den Tabellen in src/ erzeugt: das Englische dort bearbeiten)

group-water = Wasser
group-drops = Tropfen
group-light = Licht
group-scene = Szene
group-objects = Objekte
group-tank = Wellenwanne
group-ambient-waves = Wellengang
group-optics = Optik
group-water-colour = Wasserfarbe
group-simulation = Simulation
group-debug = Debug
group-display = Anzeige
group-flat-water = Ebenes Wasser
unit-cells = Zellen

## Wasser

param-wave_speed = Wellentempo
    .help = Geschwindigkeit c der Wellen in der Wellengleichung h_tt = c² ∇²h.
param-damping = Dämpfung
    .help = Rate k, mit der die Wellen Energie verlieren (die Amplitude klingt ab wie exp(-k t / 2)).
param-absorbing_walls = Absorbierende Wände
    .help = Die Wände schlucken die Wellen in einer dämpfenden Schicht entlang der Wände, statt sie zu reflektieren.
param-foam = Schaum
    .help = Weißes Wasser, wo Wellenberge schneller als mit einem Viertel von g fallen, wo Wasser an einer Wand hochläuft und wo Tropfen und Körper Wasser aufwirbeln; es verblasst und breitet sich aus.
param-foam_decay = Schaumdauer
    .help = Zeitkonstante tau, mit der der Schaum verblasst: Nach tau Sekunden sind noch 37 % davon übrig.

## Tropfen

param-drop_radius = Tropfenradius
    .help = Radius des Kosinus-Buckels, den ein Klick oder Ziehen erzeugt.
param-drop_strength = Tropfenstärke
    .help = Höhe des Buckels in seiner Mitte (negativ drückt das Wasser nach unten).
param-start_drops = Tropfen zu Beginn
    .help = Tropfen, die beim Öffnen der Seite ins Becken fallen, damit ihre Ringe und die Kaustiken, die sie werfen, sofort zu sehen sind (0: das Wasser beginnt ruhig).

## Licht

param-sun_azimuth = Sonnenazimut
    .help = Himmelsrichtung der Sonne rund um das Becken.
param-sun_elevation = Sonnenhöhe
    .help = Höhe der Sonne über dem Horizont.
param-sun_size = Sonnengröße
    .help = Winkeldurchmesser der Sonnenscheibe am Himmel und in ihren Spiegelungen (die echte Sonne: 0,5°).
param-exposure = Belichtung
    .help = Helligkeit des Bildes in Blendenstufen (jede +1 verdoppelt das Licht vor der filmischen Tonkurve), zusätzlich zur eigenen Belichtung der Kamera: Bei tieferer Sonne wird das Licht, das sie verliert, durch stärkere Belichtung ausgeglichen.
param-setting = Umgebung
    .help = Wo das Becken liegt: versenkt in einer gepflasterten Terrasse unter freiem Himmel oder, als Schnitt, im aufgeschnittenen Kasten des Klassikers, vorne offen, sodass man den Querschnitt des Wassers sieht.
param-setting-deck = Terrasse
param-setting-cutaway = Schnitt
param-caustics = Kaustiken
    .help = Licht, das die Wellen auf Boden, Wände und Kugel bündeln.
param-caustic_contrast = Kaustik-Kontrast
    .help = Wie stark die Kaustiklinien hervortreten: das gebündelte Licht hoch diese Zahl. 1 ist das Licht, das die simulierten Wellen bündeln, so wie die Kaustikkarte es speichert (über ihre Texel verwischt, die Linien also breiter und matter, als die Sonne sie zeichnen würde); 2 gibt ihnen die Helligkeit des Netzes in einem sonnigen Becken zurück.
param-tile_gloss = Fliesenglanz
    .help = Wie stark die Glasur der Fliesen spiegelt: 1 eine Keramikglasur (der Himmel und das Glanzlicht der Sonne auf den Fliesen über dem Wasser, am stärksten an ihren abgerundeten Kanten), 0 matte Fliesen.

## Szene

param-scene = Szene
    .help = Das Becken, das offene Meer bis zum Horizont unter demselben Himmel oder die Wellenwanne aus dem Schullabor mit Lampe und Schirm.
param-scene-pool = Becken
param-scene-sea = Meer
param-scene-tank = Wellenwanne
param-sea_wind = Wind
    .help = Windgeschwindigkeit über dem Meer: Stärkerer Wind verlagert die Energie der Wellen zu größeren Wellenlängen.
param-sea_wind_direction = Windrichtung
    .help = Richtung, in die der Wind weht, von +x nach +z.
param-sea_wave_height = Wellenhöhe
    .help = Signifikante Wellenhöhe: vier Standardabweichungen der Meereshöhe (etwa der Mittelwert des höchsten Drittels der Wellen).
param-sea_choppiness = Kabbelung
    .help = Wie weit das Wasser seitwärts zu den Wellenkämmen getragen wird, was sie zuspitzt (Tessendorfs Lambda).
param-sea_fog = Nebel
    .help = Dunst über dem Meer, der mit der Höhe dünner wird und Wasser und Himmel am Horizont zu einer Farbe angleicht.
param-sea_fog_distance = Sichtweite
    .help = Strecke, auf der der Dunst auf Meereshöhe das Licht auf 37 % abschwächt.
param-sea_island = Insel
    .help = Eine Insel mit Stränden, gesehen durch das Flachwasser um sie herum, wo die Wellen entlang der Küste schäumen: entfernt im Dunst oder am Ufer, mit ihrem Flachwasser unter dem Feld, in dem Klicks Wellen erzeugen und deren Kaustiken den Sand beleuchten.
param-sea_island-none = keine
param-sea_island-offshore = entfernt
param-sea_island-shore = am Ufer
param-sea_grid = Gitter zeigen
    .help = Umreißt die Zellen des Gitters, auf dem das Meer gezeichnet wird: Es liegt über dem Bildschirm und wird auf das Wasser projiziert, sodass seine Zellen auf dem Bildschirm etwa gleich groß bleiben, klein in deiner Nähe und lang gestreckt zum Horizont hin.

## Objekte

param-sea_objects = Objekte
    .help = Was im Meer schwimmt: Kugel, Ente und Wasserball des Beckens, um so viel größer, wie das Feld mit simuliertem Wasser größer ist als das Becken. Sie reiten auf den Wellen und hinterlassen Kielwellen im Feld.
param-sea_objects-none = keine
param-sea_objects-sphere = Kugel
param-sea_objects-duck = Ente
param-sea_objects-both = beide
param-sea_objects-ball = Ball
param-sea_objects-all = alle
param-objects = Objekte
    .help = Was im Becken schwimmt: beliebige aus Kugel, Gummiente und Wasserball (als Liste, z. B. sphere,duck), alle oder keine.
param-objects-none = keine
param-objects-sphere = Kugel
param-objects-duck = Ente
param-objects-both = beide
param-objects-ball = Ball
param-objects-all = alle
param-sphere_radius = Kugelradius
    .help = Radius der Kugel.
param-sphere_density = Kugeldichte
    .help = Masse pro Volumen; unter der Dichte von Wasser, 1000 kg/m³, schwimmt die Kugel.
param-duck_density = Entendichte
    .help = Masse pro Volumen der Gummiente: Je leichter sie ist, desto höher schwimmt sie.
param-ball_radius = Ballradius
    .help = Radius des Wasserballs.
param-ball_density = Balldichte
    .help = Masse pro Volumen des Wasserballs (Luft in einer dünnen Hülle, mit etwas Sand darin, damit er weniger schaukelt): leicht, daher liegt er hoch auf dem Wasser.
param-gravity = Schwerkraft
    .help = Lässt die Objekte fallen, schwimmen, schaukeln und auf den Wellen treiben (Taste G); ausgeschaltet bleiben sie, wo man sie hingesetzt hat.

## Wellenwanne

param-tank_setup = Versuch
    .help = Was in der Wanne ist: ein Erreger, zwei Erreger, eine gerade Leiste, die ebene Wellen erzeugt, die Leiste hinter einer Blende mit einem oder zwei Spalten, die Leiste und eine Glasplatte, deren gerade Kante die Wellen ablenkt (Brechung), eine linsenförmige Platte, die sie in einem Brennpunkt sammelt, ein Erreger, der sich durch die Wanne bewegt (Doppler), eine gekrümmte Wand, die die Wellen der Leiste in einen Brennpunkt reflektiert (ein Parabolspiegel), eine gerade Wand gegenüber der Leiste (stehende Wellen) oder ein Glasprisma, das die Wellen der Leiste ablenkt.
param-tank_setup-dipper = Erreger
param-tank_setup-two_dippers = zwei Erreger
param-tank_setup-plane_wave = ebene Welle
param-tank_setup-single_slit = Einzelspalt
param-tank_setup-double_slit = Doppelspalt
param-tank_setup-refraction = Brechung
param-tank_setup-lens = Linse
param-tank_setup-doppler = Doppler
param-tank_setup-reflection = Reflexion
param-tank_setup-standing = stehende Welle
param-tank_setup-prism = Prisma
param-tank_look = Ansicht
    .help = Schirm zeigt das Papier unter der Wanne von oben, so wie die Klasse es sieht; Aufbau zeigt die Wellenwanne des Labors in 3D: die Lampe über der Wanne, das Wasser, das Gestell auf seinen Beinen und das Papier auf dem Tisch darunter mit dem Bild der Lampe (ziehen, um herumzugehen); geteilt zeigt beides nebeneinander.
param-tank_look-screen = Schirm
param-tank_look-apparatus = Aufbau
param-tank_look-split = geteilt
param-tank_view = Bild
    .help = Was das Bild zeigt: das Licht der Lampe auf dem Schirm unter der Wanne (jeder Wellenberg bündelt es wie eine Linse zu einer hellen Linie), die Höhe des Wassers als Farbe oder die Intensität: die Höhe zum Quadrat, gemittelt über etwa die letzte Sekunde.
param-tank_view-screen = Schirm
param-tank_view-heights = Höhen
param-tank_view-intensity = Intensität
param-tank_tool = Zeiger
    .help = Was ein Klick oder Ziehen auf der Wanne bewirkt: Tropfen setzt kleine Pulse ins Wasser; Wände zieht gerade Wände, die die Wellen nicht überqueren können, von der Stelle des Drückens bis zur Stelle des Loslassens (eine eigene Blende, ein Reflektor, ein Kasten); Radierer macht daraus wieder offenes Wasser; Sonde setzt die Sonde an die geklickte Stelle; Lineal legt ein Lineal vom Drücken bis zum Loslassen (seine Länge steht unter der Wanne: Lege es über zehn Wellenberge, um eine Wellenlänge zu messen); Verschieben bewegt einen Erreger oder die Leiste: daraufdrücken und ziehen (der angeklickte Erreger zeigt dann seine eigene Frequenz, Amplitude und Phase).
param-tank_tool-drops = Tropfen
param-tank_tool-walls = Wände
param-tank_tool-erase = Radierer
param-tank_tool-probe = Sonde
param-tank_tool-ruler = Lineal
param-tank_tool-move = Verschieben
param-tank_frequency = Frequenz
    .help = Wie oft die Erreger (oder die Leiste) auf und ab gehen. Die Wellenlänge ist die Geschwindigkeit geteilt durch die Frequenz.
param-tank_amplitude = Amplitude
    .help = Wie weit die Erreger das Wasser auf und ab bewegen. Ein Bruchteil eines Millimeters genügt: Jeder Wellenberg bündelt dann das Licht der Lampe nahe am Schirm, wie in einer gut eingestellten Wellenwanne; höhere Wellen bündeln es oberhalb des Schirms, und die Linien dort zerfallen.
param-tank_dippers = Erreger
    .help = Wie viele Erreger im Versuch „zwei Erreger“ in einer Reihe stehen, jeweils im Spaltabstand voneinander.
param-tank_phase = Phasenschritt
    .help = Wie weit jeder Erreger der Reihe seinem Nachbarn nachläuft (eine volle Schwingung entspricht 360°). Die Wellen verstärken sich dort, wo der Weg den Rückstand ausgleicht: Der Strahl dreht sich zum nachlaufenden Ende, gemäß sin θ = (Schritt/360°) λ / Abstand. So schwenkt ein Phased-Array-Radar oder ein Ultraschallkopf seinen Strahl, ohne sich zu bewegen.
param-tank_detune = Verstimmung
    .help = Wie viel schneller jeder Erreger der Reihe schwingt als der vorige. Zwei Erreger erzeugen dann eine Schwebung: Wo sich ihre Wellen Berg auf Berg trafen, treffen sie sich bald Berg auf Tal, und die ruhigen Linien wandern so oft pro Sekunde über die Wanne, wie die Verstimmung angibt; eine Reihe aus vier schwenkt ihren Strahl.
param-tank_amplitude_ratio = Amplitudenverhältnis
    .help = Wie weit jeder Erreger der Reihe das Wasser bewegt, als Anteil des vorigen. Bei zwei unterschiedlich starken Erregern sind die ruhigen Linien nicht mehr ruhig: Wo Berg auf Tal trifft, löschen sich die Wellen nur teilweise aus.
param-tank_depth = Wassertiefe
    .help = Die Tiefe des Wassers. Hier laufen die Wellen mit der Flachwassergeschwindigkeit sqrt(g d), in tieferem Wasser schneller; über einer Glasplatte ist das Wasser flacher, daher werden die Wellen dort langsamer und ändern ihre Richtung. (Die zentimeterlangen Wellen einer echten Wanne sind nicht lang gegenüber der Tiefe und werden auch von der Oberflächenspannung gezogen, daher laufen sie langsamer, und ihre Geschwindigkeit hängt von der Wellenlänge ab; diese hier nicht. Jede Lektion nutzt nur eine Frequenz, und was sie zeigt, hängt nur von den Wellenlängen ab, also stimmt es trotzdem.)
param-tank_size = Wannengröße
    .help = Die Seitenlänge der quadratischen Wanne.
param-tank_slit_width = Spaltbreite
    .help = Die Breite jeder Öffnung in der Blende.
param-tank_slit_spacing = Spaltabstand
    .help = Der Abstand zwischen den Mitten der beiden Spalte oder der beiden Erreger.
param-tank_lamp_height = Lampenhöhe
    .help = Die Höhe der Lampe über dem Wasser. Der Schirm liegt 0,5 m unter der Wanne; eine tiefere Lampe macht das Bild größer.
param-tank_source_speed = Erregertempo
    .help = Wie schnell sich der Erreger im Doppler-Versuch durch die Wanne bewegt. Vor ihm drängen sich die Wellen zusammen, hinter ihm ziehen sie sich auseinander; ist er schneller als die Wellen (etwa 0,31 m/s bei 10 mm Wasser), hinterlässt er eine Bugwelle, ein V wie hinter einem Boot.
param-tank_strobe = Stroboskop
    .help = Beleuchtet die Wanne mit so vielen Blitzen pro Sekunde (0: eine Dauerlampe). Bei der Frequenz der Erreger trifft jeder Blitz die Wellen an derselben Stelle, sodass das Muster stillsteht und sich messen lässt; knapp daneben kriechen die Wellen langsam vorwärts oder rückwärts.
param-tank_lines = Spaltlinien
    .help = Zeichnet von der Mitte zwischen den Spalten die Richtungen, in denen die Theorie das Muster vorhersagt: bei zwei Spalten die hellen Linien, d sin θ = m λ (d der Spaltabstand); bei einem Spalt die dunklen, w sin θ = m λ (w seine Breite).
param-tank_beaches = Strände
    .help = Schräge Strände entlang der Wände, die die Wellen schlucken (wie die Schaumstoff- oder Gitterstreifen einer echten Wanne), oder kahle Wände, die sie reflektieren.
param-tank_pulse = Einzelpuls
    .help = Die Erreger (oder die Leiste) erzeugen einen einzigen Wellenberg und halten dann an, jedes Mal, wenn dies eingeschaltet oder die Wanne zurückgesetzt wird, statt eines stetigen Wellenzugs: Beobachte, wie sich eine einzelne Welle ausbreitet, reflektiert wird und durch die Spalte läuft. Alle Erreger heben das Wasser im selben Moment (Phasenschritt, Verstimmung oder die eigene Phase oder Frequenz eines Erregers formen keinen Puls).
param-tank_probe = Sonde
    .help = Eine Sonde im Wasser (der Ring) und in der Bildecke die Kurve ihrer Höhe über die letzten vier Sekunden; unter der Wanne die Frequenz und der Ausschlag, die sie misst. Setze sie mit dem Werkzeug Sonde des Zeigers oder mit den beiden Schiebereglern darunter.
param-tank_probe_x = Sonde quer
    .help = Die Lage der Sonde quer über die Wanne, von der Mitte aus nach rechts, von oben gesehen mit der Leiste unten (bleibt innerhalb der Wanne).
param-tank_probe_z = Sonde längs
    .help = Die Lage der Sonde längs der Wanne, von der Mitte zur gegenüberliegenden Seite (bleibt innerhalb der Wanne).
param-tank_graph = Intensitätskurve
    .help = Eine Linie quer über die Wanne und darüber die Kurve der Intensität entlang dieser Linie (die Höhe zum Quadrat, gemittelt über etwa die letzte Sekunde): wo sich die Wellen verstärken und wo sie sich auslöschen, wie es ein Schirm weit hinter den Spalten zeigen würde.
param-tank_graph_z = Messlinie
    .help = Wo die Linie der Intensitätskurve die Wanne kreuzt, von der Mitte zur gegenüberliegenden Seite (bleibt innerhalb der Wanne).

## Wellengang

param-ambient = Wellengang
    .help = Eine Oberfläche, die sich unter deinen Wellen von selbst bewegt: keine, eine Summe laufender Sinuswellen mit spitzen Kämmen, die eigenen stehenden Wellen des Beckens (Moden), die jede Wand waagerecht treffen, Gerstner-Wellen (das Wasser bewegt sich auf Kreisen, die Kämme werden spitzer) oder ein FFT-Ozean (Tausende Wellen aus einem Spektrum).
param-ambient-none = keine
param-ambient-sines = Sinus
param-ambient-modes = Moden
param-ambient-gerstner = Gerstner
param-ambient-fft = FFT
param-wind_speed = Windstärke
    .help = Wind des Phillips-Spektrums, aus dem die Amplituden der Wellen stammen: Stärkerer Wind gibt den längeren Wellen mehr von der Höhe.
param-wind_direction = Windrichtung
    .help = Richtung, in die der Wind weht, von +x nach +z.
param-wave_height = Wellenhöhe
    .help = Signifikante Höhe H_s des Wellengangs: das Vierfache der Standardabweichung der Oberfläche.
param-wave_spread = Richtungsstreuung
    .help = Wie weit (±) die Richtungen der laufenden Wellen von der Windrichtung abweichen.
param-steepness = Steilheit Q
    .help = Gerstner-Steilheit: 0 ergibt reine Sinuswellen; gegen 1 sammelt sich das Wasser unter spitzen Kämmen (bei 1 würden sie zu scharfen Spitzen).
param-spectrum = Spektrum
    .help = Das Wellenspektrum des FFT-Ozeans: Phillips (nach Tessendorf) oder JONSWAP (gemessener Seegang bei begrenzter Streichlänge, mit schärferem Maximum; hier 100 m Streichlänge).
param-spectrum-phillips = Phillips
param-spectrum-jonswap = JONSWAP
param-fft_size = FFT-Gitter
    .help = Wellen pro Seite des Gitters des FFT-Ozeans: 128 fügt Kräuselwellen bis hinab zu 6 cm hinzu.
param-choppiness = Kabbelung
    .help = Das Wasser des FFT-Ozeans bewegt sich auch seitwärts und sammelt sich unter den Kämmen (Tessendorfs „choppy waves“); 0 ist das reine Höhenfeld.

## Optik

param-fresnel = Fresnel-Modell
    .help = Wie viel des Lichts die Oberfläche unter jedem Winkel reflektiert: die exakten Fresnelschen Formeln, dieselben aus einer Tabellentextur, Schlicks Näherung, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) oder 1-cos θ.
param-fresnel-exact = exakt
param-fresnel-table = Tabelle
param-fresnel-schlick = Schlick
param-fresnel-inverse_power = inverse Potenz
param-fresnel-clamped_power = begrenzte Potenz
param-fresnel-linear = linear
param-specular = Glanzlicht
    .help = Form des Sonnenglitzerns auf dem Wasser: Phong (reflektierter Strahl gegen Sonnenrichtung) oder Blinn-Phong (Normale gegen Halbvektor), bei gleicher Glanzschärfe breiter.
param-specular-phong = Phong
param-specular-blinn_phong = Blinn-Phong
param-shininess = Glanzschärfe
    .help = Exponent s im cos^s des Glanzlichts: Höher ergibt ein kleineres, schärferes Glitzern.
param-dispersion = Dispersion
    .help = Rotes und blaues Licht werden mit ihren eigenen Brechungsindizes gebrochen (Wasser: 1,331 rot, 1,335 grün, 1,337 blau), um diesen Faktor gegenüber der echten Aufspaltung verstärkt: farbige Säume an den Rändern der Kaustiken und am Rand von Snells Fenster. 0: aus.

## Wasserfarbe

param-absorption_red = Absorption, rot
    .help = Beer-Lambert-Absorption von rotem Licht pro Meter Wasser: Nach d Metern ist noch exp(-a d) davon übrig.
param-absorption_green = Absorption, grün
    .help = Beer-Lambert-Absorption von grünem Licht pro Meter Wasser: Nach d Metern ist noch exp(-a d) davon übrig.
param-absorption_blue = Absorption, blau
    .help = Beer-Lambert-Absorption von blauem Licht pro Meter Wasser: Nach d Metern ist noch exp(-a d) davon übrig.
param-scatter_red = Streulicht, rot
    .help = Licht, das das Wasser selbst zu dir streut (rot, lineare Einheiten; der Himmel hat etwa 0,5): Es ersetzt, was die Absorption wegnimmt, sodass tiefes Wasser diese Farbe annimmt statt schwarz zu werden. 0 in allen Kanälen: aus.
param-scatter_green = Streulicht, grün
    .help = Licht, das das Wasser selbst zu dir streut (grün, lineare Einheiten; der Himmel hat etwa 0,5): Es ersetzt, was die Absorption wegnimmt, sodass tiefes Wasser diese Farbe annimmt statt schwarz zu werden. 0 in allen Kanälen: aus.
param-scatter_blue = Streulicht, blau
    .help = Licht, das das Wasser selbst zu dir streut (blau, lineare Einheiten; der Himmel hat etwa 0,5): Es ersetzt, was die Absorption wegnimmt, sodass tiefes Wasser diese Farbe annimmt statt schwarz zu werden. 0 in allen Kanälen: aus.
param-view_colour = Farbe nach Blickwinkel
    .help = Das Streulicht verliert auf streifenden Wegen die Hälfte seines Grüns und behält es beim Blick senkrecht nach unten, so wie Spiele Wasser nach dem Blickwinkel einfärben (braucht Streulicht).

## Simulation

param-sim_size = Gitterauflösung
    .help = Zellen pro Seite des Simulationsgitters; eine Änderung tastet das Wasser neu ab, sie setzt es nicht zurück.
param-paused = Angehalten
    .help = Friert das Wasser ein (Leertaste).

## Debug

param-debug_view = Debug-Ansicht
    .help = Zeigt eine der Texturen der Simulation: Höhe (rot nach oben, blau nach unten), Oberflächennormalen, vertikale Geschwindigkeit oder die Kaustik-Karte; oder den Fresnel-Reflexionsgrad des Wassers als Grauwert (schwarz 0, weiß 1); oder das Spektrum des Wellengangs (Amplitude pro Wellenvektor, logarithmische Skala, k = 0 in der Mitte, Ringe bei 0,9 m und 0,2 m Wellenlänge).
param-debug_view-off = aus
param-debug_view-height = Höhe
param-debug_view-normals = Normalen
param-debug_view-velocity = Geschwindigkeit
param-debug_view-caustics = Kaustiken
param-debug_view-reflectance = Reflexionsgrad
param-debug_view-spectrum = Spektrum
param-debug_inset = Debug-Ansicht in der Ecke
    .help = Zeigt die Debug-Ansicht in einer Ecke der Szene (an) oder über die ganze Szene (aus).

## Anzeige

param-quality = Auflösung
    .help = Skalierung der Auflösung der Szene: fest oder auto (in Stufen bis auf 50 % gesenkt, solange Bilder länger als die Zeit pro Bild brauchen, und wieder erhöht, wenn Spielraum da ist).
param-quality-auto = auto
param-frame_budget = Zeit pro Bild
    .help = Zeit, die ein Bild höchstens dauern soll; bei automatischer Auflösung senken langsamere Bilder die Auflösung.

## Ebenes Wasser

param-render_mode = Wasserdarstellung
    .help = Wie die Wasseroberfläche gezeichnet wird. Raytracing: Jedes Pixel der Oberfläche verfolgt seine reflektierten und gebrochenen Strahlen durch das Becken. Ebene: die Technik aus Spielen: Die Szene wird zweimal zusätzlich in Texturen gezeichnet, an der Wasserebene gespiegelt (Reflexion) und unter ihr abgeschnitten (Brechung), und eine flache Ebene mischt beide nach Fresnel, verwackelt durch eine Verzerrung statt von den Wellen gebrochen. Das ist eine Technik für über Wasser: Unter Wasser zeichnet der Raytracer. geteilt: Ebene links, Raytracing rechts einer Trennlinie, die du ziehen kannst.
param-render_mode-raytraced = Raytracing
param-render_mode-flat = Ebene
param-render_mode-split = geteilt
param-split = Trennlinie
    .help = Wo die Trennlinie steht, als Anteil der Breite von links: links davon ebenes Wasser, rechts Raytracing. Ziehe die Trennlinie im Bild, um sie zu verschieben.
param-flat_distortion = Verzerrung
    .help = Was Spiegelung und Brechung des ebenen Wassers verwackelt: dudv, eine sich wiederholende Verzerrungskarte (eine dUdV-Map), die mit der Zeit weiterläuft (Klicks erzeugen darin keine Wellen), oder Wellen, die Neigungen der Simulation selbst (dieselben Wellen wie beim Raytracer, mit vorgetäuschter Optik).
param-flat_distortion-dudv = dudv
param-flat_distortion-ripples = Wellen
param-flat_strength = Verzerrungsstärke
    .help = Wie weit die Spiegelungs- und Brechungstexturen durch die Verzerrung verschoben werden, als Anteil des Bildschirms. Anders als echte Brechung wächst sie nicht mit dem Abstand zum Gesehenen: Ein Beckenrand weit über dem Wasser wackelt genauso stark wie die Fliesen darunter.
param-dudv_speed = Verzerrungstempo
    .help = Kacheln der dudv-Karte, die pro simulierter Sekunde weiterlaufen (sie steht still, wenn das Wasser angehalten ist); bei der Verzerrung dudv.
param-flat_resolution = Texturauflösung
    .help = Größe der Spiegelungs- und Brechungstexturen im Verhältnis zur Szene: kleiner ist schneller und unschärfer.
param-flat_caustics = Kaustiken
    .help = Licht auf dem Becken unter ebenem Wasser: aus (wie bei ruhiger Oberfläche), unecht (ein Glanzpunkt, wo die Normale der Verzerrung die Sonne senkrecht nach unten lenken würde; keine Bündelung, kein zusätzlicher Durchgang) oder echt (die Kaustik-Karte des Raytracers, ein Durchgang mehr).
param-flat_caustics-off = aus
param-flat_caustics-fake = unecht
param-flat_caustics-real = echt
param-flat_soft_edge = Weicher Rand
    .help = Wasser, das (entlang der Blickrichtung) flacher als dieser Wert ist, wird weniger verzerrt; das verbirgt die Naht, wo die Ebene auf die Wände trifft; 0 zeigt die Naht.

## Die eigenen Einstellungen jedes Erregers in der Wanne (Titel der Gruppe: „Erreger“ und seine Nummer)

param-frequency = Eigene Frequenz
    .help = Wie oft dieser Erreger auf und ab geht. Zwei Erreger mit leicht verschiedener Frequenz erzeugen eine Schwebung: Ihre ruhigen Linien wandern über die Wanne.
param-amplitude = Eigene Amplitude
    .help = Wie weit dieser Erreger das Wasser bewegt (0 stellt ihn still). Wo die Wellen eines starken und eines schwachen Erregers Berg auf Tal treffen, löschen sie sich nur teilweise aus.
param-phase = Eigene Phase
    .help = Wie weit dieser Erreger der eingestellten Phase vorausläuft (eine volle Schwingung entspricht 360°; negativ: er läuft nach). Zwei Erreger mit 180° Phasenunterschied schicken Berg gegen Tal: Die Mittellinie zwischen ihnen bleibt ruhig.

## Vorlagen (der Name und was Schülerinnen und Schüler lesen)

preset-classic = Der Klassiker
    .help = Eine Kugel, die bleibt, wo man sie hinsetzt (G lässt sie fallen), reflektierende Wände, Kaustiken: das Becken, wie es das klassische WebGL Water zeigt.
preset-calm = Ruhiges Wasser
    .help = Nichts im Becken, kleine Tropfen, Wellen, die an absorbierenden Wänden schnell abklingen: eine ruhige Oberfläche, um eine Welle nach der anderen zu untersuchen.
preset-busy = Ein belebtes Becken
    .help = Kugel und Ente schwimmen auf schnellem, lebhaftem Wasser mit großen Tropfen und reflektierenden Wänden.
preset-fresnel = Lektion: Fresnel-Reflexion
    .help = Ruhiges, leeres Wasser, flach über das Becken gesehen, sodass der Einfallswinkel von etwa 50° vor dir bis zu streifendem Einfall auf der anderen Seite reicht: Wechsle das Fresnel-Modell und beobachte, wie sich Spiegelung und Diagramm ändern.
preset-glint = Lektion: das Glitzern der Sonne
    .help = Blick zu einer tiefen Sonne: Ziehe über das Wasser, um Wellen zu erzeugen, und sieh, wie das Blinn-Phong-Glitzern entlang der Blickrichtung gestreckt ist; stelle Glanzlicht auf Phong und ändere die Glanzschärfe zum Vergleich.
preset-breeze = Lektion: Wellengang
    .help = Eine leichte Brise lässt Wellen mit spitzen Kämmen unter deinen Wellen über das Becken laufen; stelle Wellengang auf Moden, um die eigenen stehenden Wellen des Beckens zu sehen, die jede Wand waagerecht treffen, auf Gerstner für Wasser, das sich auf Kreisen bewegt, oder auf FFT für ein Spektrum aus Tausenden Wellen (die Debug-Ansicht Spektrum zeigt die Wellen jedes Modells).
preset-ocean = Lektion: ein FFT-Ozean
    .help = Tessendorfs Ozean im Becken: ein Phillips-Spektrum aus etwa tausend Wellen auf einem Gitter mit 128 Punkten, in jedem Bild per FFT summiert; die Debug-Ansicht zeigt das Spektrum, in Windrichtung ausgerichtet.
preset-flat = Lektion: ebenes Wasser gegen Raytracing
    .help = Das ebene Wasser der Spiele (links) gegen den Raytracer (rechts), die Kugel halb aus dem Wasser: Ziehe die Trennlinie über die Kugel. Links sitzt ihre untergetauchte Hälfte ungebrochen in ihrer wahren Tiefe, und die Spiegelungen wackeln um eine feste Verschiebung; rechts hebt das Wasser sie scheinbar an und bricht alles nach den Neigungen der Wellen. Erzeuge Wellen und stelle Verzerrung auf Wellen, um dieselben Wellen mit vorgetäuschter Optik zu sehen.
preset-lake = Lektion: Wasserfarbe
    .help = Grünes Seewasser: Es absorbiert Rot, Grün und Blau schneller als das Wasser des Beckens und streut selbst ein grünblaues Licht, sodass das tiefe Ende grün statt dunkel wird (stelle das Streulicht auf 0, um reines Beer-Lambert zu sehen).
preset-noon = Mittag
    .help = Die Sonne fast im Zenit: ein tiefblauer Himmel, kurze Schatten, die hellsten Kaustiken am Boden.
preset-evening = Abend
    .help = Eine tiefe, warme Sonne von der Seite, das Bild für sie belichtet: lange Schatten über die Terrasse, das Wasser dunkel, wo der Rand es beschattet, die hintere Wand von den Kaustiken der Sonne beleuchtet.
preset-sea = Lektion: das offene Meer
    .help = Offenes Wasser bis zum Horizont bei mäßiger Brise: fünf FFT-Kaskaden mit verschiedenen Kachelgrößen, sodass sich kein Muster wiederholt; das Gitter, auf dem das Meer gezeichnet wird, ist vom Bildschirm aus projiziert, sodass seine Details deinem Blick folgen; der Dunst gleicht Meer und Himmel am Horizont zu einer Farbe an (schalte Nebel aus, um den Rand des Meeres zu sehen); die Insel voraus steht in türkisem Flachwasser mit Schaum entlang der Küste und spiegelt sich im Wasser (schalte Gitter zeigen ein, um das Gitter zu sehen). Klicke nahe der Mitte, um Wellen im Feld mit simuliertem Wasser zu erzeugen, und sieh zu, wie sie auslaufen; die Gummiente dort, um so viel größer, wie das Feld größer ist als das Becken, reitet auf den Wellen und hinterlässt eine Kielwelle: Ziehe sie, um eine zu sehen.
preset-shore = Lektion: Wellen im Flachwasser
    .help = Der Strand der Insel am Feld mit simuliertem Wasser, bei leichter Brise unter hoher Sonne: Die Neigungen der Wellen bündeln das Sonnenlicht zu einem Netz aus Kaustiken auf dem Sand wenige Meter tiefer. Klicke ins Wasser, um Wellen zu erzeugen: Wo die Tiefe passt, bündeln sich ihre Ringe zu hellen Linien am Boden, die sie viel besser zeigen als die Oberfläche selbst. Das Schaukeln der Ente zeichnet eigene Ringe, und ihr Schatten liegt auf dem Sand.
preset-dawn = Ruhige See im Morgengrauen
    .help = Eine tiefe Sonne voraus über ruhiger See: ihr Glitzern zu einem langen, funkelnden Pfad auf den kleinen Wellen verteilt, der Himmel warm entlang des Horizonts.
preset-storm = Sturm auf See
    .help = Starker Wind türmt 5 m hohe Wellen mit zugespitzten Kämmen auf, unter tiefer Sonne, in dichtem Dunst; die Ente wird zwischen den Schaumkronen hin und her geworfen.
preset-tank = Wellenwanne: ein Erreger
    .help = Eine Wellenwanne wie in der Schule, von oben gesehen: Ein Erreger wippt zehnmal pro Sekunde in der Mitte einer Wanne mit 10 mm tiefem Wasser, und die Lampe über der Wanne wirft seine Ringe als helle Kreise auf den Schirm darunter, weil jeder Wellenberg das Licht wie eine Linse bündelt. Stelle Bild auf Höhen, um die Wellen selbst zu sehen; ändere die Frequenz und sieh, wie die Ringe enger zusammenrücken (die Wellenlänge ist die Geschwindigkeit geteilt durch die Frequenz).
preset-single_slit = Wellenwanne: ein Spalt
    .help = Eine gerade Leiste erzeugt ebene Wellen, die auf eine Blende mit einer Öffnung treffen. Hinter der Öffnung breiten sie sich fächerförmig aus; je schmaler die Öffnung im Vergleich zur Wellenlänge, desto breiter der Fächer (probiere die Spaltbreite aus).
preset-double_slit = Wellenwanne: zwei Spalte
    .help = Ebene Wellen durch zwei Öffnungen im Abstand von 90 mm: Die Wellen aus beiden Öffnungen kreuzen sich, und wo Berg auf Berg trifft, zeigt der Schirm helle Linien, während dazwischen, wo Berg auf Tal trifft, das Wasser ruhig bleibt. Die ruhigen Linien fächern sich unter den Winkeln auf, bei denen sich die Wege um eine halbe Wellenlänge unterscheiden; stelle Bild auf Intensität, um sie zu sehen.
preset-refraction = Wellenwanne: Brechung
    .help = Ebene Wellen laufen auf eine Glasplatte unter Wasser. Das Wasser darüber ist flacher, daher werden die Wellen langsamer und rücken enger zusammen, und wo sie die schräge Kante der Platte überqueren, ändern sie ihre Richtung: das Brechungsgesetz von Snell für Wasserwellen.
preset-lens = Wellenwanne: eine Linse
    .help = Eine linsenförmige Glasplatte unter Wasser: Die Wellen werden darüber langsamer, und die Mitte jeder Wellenfront verbringt die längste Zeit über der Platte, sodass die geraden Fronten gekrümmt herauskommen und sich in einem Brennpunkt dahinter treffen, wie Licht hinter einer Glaslinse.
preset-doppler = Wellenwanne: eine bewegte Quelle
    .help = Ein Erreger bewegt sich mit 0,12 m/s durch die Wanne, etwa 40 % der Wellengeschwindigkeit: Vor ihm drängen sich die Wellenberge zusammen, hinter ihm ziehen sie sich auseinander, so wie der Ton einer vorbeifahrenden Sirene erst höher und dann tiefer klingt. Erhöhe sein Tempo über das der Wellen (etwa 0,31 m/s), und er überholt seine eigenen Wellen: eine Bugwelle.
preset-reflection = Wellenwanne: ein Hohlspiegel
    .help = Gerade Wellen laufen auf eine gekrümmte Wand in Form einer Parabel. Jeder Teil der Wand wirft sie unter seinem eigenen Winkel zurück, und alle treffen sich in einem Punkt davor, dem Brennpunkt, wie Licht im Spiegel einer Taschenlampe oder in einer Satellitenschüssel. Stelle Bild auf Intensität, um den hellen Brennpunkt zu sehen.
preset-standing = Wellenwanne: stehende Wellen
    .help = Gerade Wellen laufen auf eine gerade Wand und kommen durch sich selbst zurück. Wo sie sich treffen, überlagern sie sich zu stehenden Wellen: Linien ruhigen Wassers (Knoten) im Abstand einer halben Wellenlänge und dazwischen Wasser, das auf und ab geht, ohne sich fortzubewegen. Stelle Bild auf Höhen und das Stroboskop auf die Frequenz der Erreger.
preset-phased_array = Wellenwanne: ein Phased Array
    .help = Vier Erreger in einer Reihe, 30 mm voneinander entfernt (etwas mehr als eine halbe Wellenlänge bei 6 Hz), jeder eine Viertelschwingung hinter dem vorigen. Ihre Wellen verstärken sich nur in einer Richtung, zu einem Strahl, der um etwa 25° zum nachlaufenden Ende gedreht ist: Ändere den Phasenschritt, und der Strahl schwenkt herum, ohne dass sich etwas bewegt, so wie ein Phased-Array-Radar oder ein Ultraschallkopf seinen Strahl lenkt. Stelle Bild auf Intensität, um den Strahl zu sehen.
