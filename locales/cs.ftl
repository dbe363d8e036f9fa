# Slova aplikace wavepool v češtině, přeložená ze zdrojového katalogu en.ftl (Project Fluent,
# https://projectfluent.org/fluent/guide/). Jazyk se přidá zkopírováním en.ftl do
# locales/<tag>.ftl, přeložením textu každé zprávy (nikdy jejího id ani jejích { $variables }) a
# registrací značky ve web/i18n.js (LANGUAGES). Značky jednotek (m/s, Hz, °) a vlastní jména
# zůstávají beze změny.

## Slova samotné stránky (web/*.js)

language = Jazyk
controls = Ovládání
preset = Předvolba
    .title = Začít znovu z nastavení a pohledu lekce
preset-choose = vyberte…
preset-applied = Předvolba { $name } použita.
preset-press-enter = Stisknutím Enter použijete předvolbu { $name }.
reset = Resetovat
    .title = Zpět do stavu, v jakém se stránka otevřela: její parametry a pohled, klidná voda, předměty na svých místech
defaults = Výchozí
    .title = Nastavit všechny parametry na výchozí hodnoty
share-link = Sdílet odkaz
    .title = Zkopírovat odkaz, který otevře tento bazén s těmito parametry a tímto pohledem
embed-code = Kopírovat kód pro vložení
    .title = Zkopírovat <iframe>, který na jiné stránce ukáže tento bazén tak, jak je teď
link-copied = Odkaz zkopírován.
embed-code-copied = Kód pro vložení zkopírován.
embed-title = Interaktivní bazén s vodou (wavepool)
fullscreen = Celá obrazovka
    .title = Celá obrazovka (Esc ji ukončí)
play = Spustit
    .title = Spustit: voda a předměty se dají do pohybu
pause = Pozastavit
    .title = Pozastavit: voda a předměty se zastaví
on = zapnuto
off = vypnuto
dipper = Budič { $number }
notice-no-gpu = Tento prohlížeč kreslí bez GPU, proto jsou největší velikosti zmenšeny, aby zůstal svižný: { $sizes }.
notice-slow-resolution = Snímky tu trvaly déle než sekundu: rozlišení je nyní automatické.
notice-slow-grid = Snímky tu trvaly déle než sekundu: simulační mřížka je zmenšena na { $cells } buněk.
fresnel-plot = Odrazivost v závislosti na úhlu dopadu: zvolený Fresnelův model nad přesnou křivkou
fresnel-angle = úhel dopadu
fresnel-caption = Odrazivost: zvolený model (modře) proti přesnému (šedě); ze vzduchu plnou čarou, zpod vody čárkovaně; | váš pohled
status-loading = Načítám vodu…
status-device-lost = Grafické zařízení bylo ztraceno; spouštím znovu…
status-waiting = Čekám na volný kontext GPU: posuňte jinou ukázku s vodou na této stránce mimo obrazovku.
page-intro = Klepnutím nebo tažením po vodě vytvoříte vlnky, tažením plovoucího předmětu ho přesunete, tažením jinde otočíte kamerou; kolečkem nebo sevřením prstů přibližujete. Když je ukázka aktivní: mezerník pozastaví, G upustí předměty, L postaví slunce za vás.
page-starting = Spouštím vodu…
page-running = Běží na { $api }, { $adapter }.
page-running-unnamed = Běží na { $api } (prohlížeč neprozrazuje, na jakém GPU).
page-failed = Voda se zde nemohla spustit: proč, říká rámeček níže.
error-backend-forced = Tato stránka žádala jen { $api } (backend={ $backend }) a tento prohlížeč ho nedokázal spustit:
error-backend-forced-fix = Odstraňte backend={ $backend } z adresy nebo z voleb (nebo nastavte backend=auto), aby si ukázka vybrala rozhraní, které tento prohlížeč má.
error-no-backend = Tento prohlížeč nedokázal spustit ukázku s vodou: nefungovalo ani WebGPU, ani WebGL2 (grafická akcelerace může být v jeho nastavení vypnutá).
error-no-webgpu = WebGPU: tento prohlížeč ho nenabízí (chybí navigator.gpu)
error-stopped = Ukázka s vodou se zastavila: { $reason }
error-device-lost = Grafické zařízení bylo ztraceno a nepodařilo se ho znovu spustit: { $reason }
error-crashed = Ukázka s vodou spadla: { $reason }
error-restart = Ukázku s vodou se nepodařilo znovu spustit: { $reason }
fallback-picture = Statický obrázek bazénu s vodou (živou ukázku zde nešlo spustit)
canvas-label = Bazén s vodou. Tažením po vodě vytvoříte vlnky, tažením koule ji přesunete, tažením jinde otočíte kamerou. Klávesy: šipky otáčejí, + a - přibližují, Enter pustí kapku doprostřed, mezerník pozastaví, G gravitace, L světlo.
costs-gpu = Čas GPU při kreslení vody: { $times }.
costs-no-gpu-time = Čas GPU: tento prohlížeč ho neměří (WebGPU bez časových značek).
costs-between = Mezi snímky: { $times }.
note-flat-under-water = Plochá voda je technika pro pohled nad vodou: pod vodou kreslí sledování paprsků.
reading-probe-frequency = Frekvence sondy
reading-probe-swing = Výchylka sondy
reading-ruler = Pravítko
viewer-reset-water = Vyhladit vodu
    .title = Uklidní vodu a vrátí kouli na místo
viewer-frame = snímek: { $cpu } ms CPU, { $between } ms mezi snímky
viewer-gpu = GPU: { $stages }
viewer-gpu-none = Čas GPU: toto zařízení nemá časové dotazy
viewer-gpu-waiting = Čas GPU: čekám na první časové značky
viewer-costs = kreslení vody (kaustiky + stínování): { $costs }
viewer-water = voda: { $cells }² buněk, { $seconds } s simulováno
viewer-adapter = adaptér: { $name }
stage-simulation = simulace
stage-caustics = kaustiky
stage-maps = mapy
stage-screen = stínítko
stage-shading = stínování
stage-the-tank = vana
stage-waves = vlny
viewer-reset-one = výchozí
    .title = Vrátit na výchozí hodnotu

## The parameter table and the presets
## (zapisuje `wavepool messages` z tabulek v src/: anglický text upravujte tam)

group-water = Voda
group-drops = Kapky
group-light = Světlo
group-scene = Scéna
group-objects = Předměty
group-tank = Vlnová vana
group-ambient-waves = Vlny na pozadí
group-optics = Optika
group-water-colour = Barva vody
group-simulation = Simulace
group-debug = Ladění
group-display = Zobrazení
group-flat-water = Plochá voda
unit-cells = buněk

## Voda

param-wave_speed = Rychlost vln
    .help = Rychlost c vlnek ve vlnové rovnici h_tt = c² ∇²h.
param-damping = Útlum
    .help = Rychlost k, s jakou vlny ztrácejí energii (amplituda klesá jako exp(-k t / 2)).
param-absorbing_walls = Pohlcující stěny
    .help = Stěny vlny pohlcují v tlumicí vrstvě podél sebe, místo aby je odrážely.
param-foam = Pěna
    .help = Bílá pěna tam, kde hřebeny padají se zrychlením větším než čtvrtina g, kde voda vybíhá na stěnu a kde kapky a tělesa rozstřikují vodu; postupně slábne a rozplývá se.
param-foam_decay = Životnost pěny
    .help = Časová konstanta tau mizení pěny: po tau sekundách z ní zbývá 37 %.

## Kapky

param-drop_radius = Poloměr kapky
    .help = Poloměr kosinového hrbolu, který přidá kliknutí nebo tažení.
param-drop_strength = Síla kapky
    .help = Výška hrbolu v jeho středu (záporná vodu stlačí dolů).
param-start_drops = Kapky na začátku
    .help = Kapky, které dopadnou do bazénu při otevření stránky, aby se jejich kruhy a kaustiky, které vrhají, ukázaly hned (0: voda začne klidná).

## Světlo

param-sun_azimuth = Azimut slunce
    .help = Směr ke slunci podle kompasu, kolem bazénu.
param-sun_elevation = Výška slunce
    .help = Výška slunce nad obzorem.
param-sun_size = Velikost slunce
    .help = Úhlový průměr slunečního kotouče na obloze a v jeho odrazech (skutečné slunce: 0,5°).
param-exposure = Expozice
    .help = Jas obrazu ve fotografických expozičních stupních (každé +1 zdvojnásobí světlo před filmovou tónovou křivkou), navíc k vlastní expozici kamery: nižší slunce se exponuje na světlo, o které přichází.
param-setting = Prostředí
    .help = Kde bazén je: zapuštěný v dlážděné terase pod oblohou, nebo v řezu jako v klasické verzi, otevřený u bližších stěn, takže vidíte průřez vodou.
param-setting-deck = terasa
param-setting-cutaway = řez
param-caustics = Kaustiky
    .help = Světlo soustředěné vlnami na dno, stěny a kouli.
param-caustic_contrast = Kontrast kaustik
    .help = Jak výrazně kaustické čáry vystupují: soustředěné světlo umocněné tímto exponentem. 1 je světlo, které simulované vlny soustředí, jak ho drží mapa kaustik (rozmazané přes její texely, takže čáry jsou širší a slabší, než by je nakreslilo slunce); 2 jim vrací jas sítě ve slunném bazénu.
param-tile_gloss = Lesk dlaždic
    .help = Jak moc glazura dlaždic zrcadlí: 1 keramická glazura (obloha a odlesk slunce na dlaždicích nad vodou, nejvíc na jejich zaoblených hranách), 0 matné dlaždice.

## Scéna

param-scene = Scéna
    .help = Bazén, otevřené moře až k obzoru pod stejnou oblohou, nebo vlnová vana ze školní laboratoře s lampou a stínítkem.
param-scene-pool = bazén
param-scene-sea = moře
param-scene-tank = vlnová vana
param-sea_wind = Vítr
    .help = Rychlost větru nad mořem: silnější vítr přesouvá energii vln k delším vlnovým délkám.
param-sea_wind_direction = Směr větru
    .help = Směr, kam vítr vane, od +x k +z.
param-sea_wave_height = Výška vln
    .help = Významná výška vln: čtyři směrodatné odchylky výšky mořské hladiny (zhruba průměr nejvyšší třetiny vln).
param-sea_choppiness = Rozbouřenost
    .help = Jak daleko se voda posouvá do stran k hřebenům a zostřuje je (lambda podle Tessendorfa).
param-sea_fog = Mlha
    .help = Opar nad mořem, řídnoucí s výškou, který na obzoru slévá vodu a oblohu do jedné barvy.
param-sea_fog_distance = Vzdálenost mlhy
    .help = Vzdálenost, na které opar u hladiny moře zeslabí světlo na 37 %.
param-sea_island = Ostrov
    .help = Ostrov s plážemi, viděný přes mělčiny kolem něj, kde vlny pění podél břehu: v dálce v oparu, nebo u břehu, s mělčinami pod oblastí, kde kliknutí vytváří vlnky a kaustiky vlnek osvětlují písek.
param-sea_island-none = žádný
param-sea_island-offshore = v dálce
param-sea_island-shore = u břehu
param-sea_grid = Zobrazit mřížku
    .help = Obtáhne buňky mřížky, na které se moře kreslí: leží na obrazovce a promítá se na vodu, takže její buňky mají na obrazovce zhruba stejnou velikost, malé blízko vás a protáhlé směrem k obzoru.

## Předměty

param-sea_objects = Předměty
    .help = Co plave v moři: koule, kachna a plážový míč z bazénu, zvětšené tolikrát, kolikrát je oblast simulované vody větší než bazén. Houpou se na vlnách a zanechávají v oblasti brázdy.
param-sea_objects-none = nic
param-sea_objects-sphere = koule
param-sea_objects-duck = kachna
param-sea_objects-both = obojí
param-sea_objects-ball = míč
param-sea_objects-all = vše
param-objects = Předměty
    .help = Co plave v bazénu: libovolné z koule, gumové kachničky a plážového míče (jako seznam, např. sphere,duck), vše nebo nic.
param-objects-none = nic
param-objects-sphere = koule
param-objects-duck = kachna
param-objects-both = obojí
param-objects-ball = míč
param-objects-all = vše
param-sphere_radius = Poloměr koule
    .help = Poloměr koule.
param-sphere_density = Hustota koule
    .help = Hmotnost na jednotku objemu; pod hustotou vody 1000 kg/m³ koule plave.
param-duck_density = Hustota kachny
    .help = Hmotnost na jednotku objemu gumové kachničky: čím je lehčí, tím výš plave.
param-ball_radius = Poloměr míče
    .help = Poloměr plážového míče.
param-ball_density = Hustota míče
    .help = Hmotnost na jednotku objemu plážového míče (vzduch v tenké slupce a v něm trocha písku, aby se méně houpal): je lehký, takže plave vysoko na vodě.
param-gravity = Gravitace
    .help = Předměty padají, plavou, pohupují se a vlny je unášejí (klávesa G); když je vypnutá, zůstanou tam, kam je položíte.

## Vlnová vana

param-tank_setup = Uspořádání
    .help = Co je ve vaně: jeden budič, dva budiče, rovná lišta vytvářející rovinné vlny, lišta za překážkou s jednou nebo dvěma štěrbinami, lišta a skleněná destička, na jejímž rovném okraji se vlny lámou (lom), destička ve tvaru čočky, která je soustředí do ohniska, budič pohybující se přes vanu (Dopplerův jev), zakřivená stěna, která odráží vlny od lišty do ohniska (parabolické zrcadlo), rovná stěna naproti liště (stojaté vlny), nebo skleněný hranol, který vlny od lišty stáčí stranou.
param-tank_setup-dipper = budič
param-tank_setup-two_dippers = dva budiče
param-tank_setup-plane_wave = rovinná vlna
param-tank_setup-single_slit = jedna štěrbina
param-tank_setup-double_slit = dvojštěrbina
param-tank_setup-refraction = lom
param-tank_setup-lens = čočka
param-tank_setup-doppler = Doppler
param-tank_setup-reflection = odraz
param-tank_setup-standing = stojaté vlny
param-tank_setup-prism = hranol
param-tank_look = Pohled
    .help = Pohled stínítko ukazuje papír pod vanou shora, jak se na něj dívá třída; aparatura ukazuje laboratorní vanu ve 3D: lampu nad vanou, vodu, rám na nohách a papír na stole pod ní s obrazem lampy (tažením ji obejdete); vedle sebe ukazuje obojí současně.
param-tank_look-screen = stínítko
param-tank_look-apparatus = aparatura
param-tank_look-split = vedle sebe
param-tank_view = Zobrazení
    .help = Co obraz ukazuje: světlo lampy na stínítku pod vanou (každý hřeben ho soustředí jako čočka do světlé čáry), výšky vody jako barvu, nebo intenzitu: druhou mocninu výšky zprůměrovanou zhruba za poslední sekundu.
param-tank_view-screen = stínítko
param-tank_view-heights = výšky
param-tank_view-intensity = intenzita
param-tank_tool = Nástroj
    .help = Co dělá kliknutí nebo tažení na vaně: kapky pouštějí do vody malé pulzy; stěny kreslí rovné stěny, přes které vlny neprojdou, od místa stisku k místu uvolnění (vlastní překážka, odrazná plocha, ohrádka); mazání vrací volnou vodu; sonda se umístí tam, kam kliknete; pravítko se položí od místa stisku k místu uvolnění (jeho délka se ukáže pod vanou: položte ho přes deset hřebenů a změříte vlnovou délku); přesun posouvá budič nebo lištu: stiskněte na něm tlačítko a táhněte (budič, na který kliknete, pak ukáže svou vlastní frekvenci, amplitudu a fázi).
param-tank_tool-drops = kapky
param-tank_tool-walls = stěny
param-tank_tool-erase = mazání
param-tank_tool-probe = sonda
param-tank_tool-ruler = pravítko
param-tank_tool-move = přesun
param-tank_frequency = Frekvence
    .help = Jak často se budiče (nebo lišta) pohybují nahoru a dolů. Vlnová délka je rychlost dělená frekvencí.
param-tank_amplitude = Amplituda
    .help = Jak vysoko budiče rozkmitají vodu nahoru a dolů. Stačí zlomek milimetru: každý hřeben pak soustředí světlo lampy poblíž stínítka jako v dobře seřízené laboratorní vaně; vyšší vlny ho soustředí nad stínítkem a čáry se tam rozpadají.
param-tank_dippers = Počet budičů
    .help = Kolik budičů stojí v řadě v uspořádání se dvěma budiči, vzdálených od sebe o rozteč štěrbin.
param-tank_phase = Fázový krok
    .help = O kolik se každý budič v řadě zpožďuje za sousedem (celý cyklus je 360°). Vlny se sčítají tam, kde zpoždění vyrovná dráha: svazek se stáčí ke zpožděnému konci podle sin θ = (krok/360°) λ / rozteč. Tak fázované anténní pole radaru nebo ultrazvuková sonda směruje svůj svazek, aniž by se pohnula.
param-tank_detune = Rozladění
    .help = O kolik rychleji běží každý budič v řadě než ten před ním. Dva budiče pak vytvářejí rázy: kde se jejich vlny potkávaly hřebenem s hřebenem, brzy se potkávají hřebenem s důlem, a klidné čáry přebíhají přes vanu tolikrát za sekundu; řada čtyř budičů rozmítá svůj svazek.
param-tank_amplitude_ratio = Poměr amplitud
    .help = Jak silně každý budič v řadě rozkmitá vodu v poměru k tomu před ním. Se dvěma nestejně silnými budiči už klidné čáry nejsou klidné: kde se hřeben potká s důlem, vlny se vyruší jen zčásti.
param-tank_depth = Hloubka vody
    .help = Hloubka vody. Vlny tu běží rychlostí vln na mělké vodě sqrt(g d), v hlubší vodě rychleji; nad skleněnou destičkou je voda mělčí, takže se tam vlny zpomalí a ohnou. (Centimetrové vlnky ve skutečné vaně nejsou vůči hloubce dlouhé a působí na ně i povrchové napětí, takže běží pomaleji a jejich rychlost závisí na vlnové délce; tyto ne. Každá lekce používá jednu frekvenci a to, co ukazuje, závisí jen na vlnových délkách, takže to platí.)
param-tank_size = Velikost vany
    .help = Strana čtvercové vany.
param-tank_slit_width = Šířka štěrbiny
    .help = Šířka každé mezery v překážce.
param-tank_slit_spacing = Rozteč štěrbin
    .help = Vzdálenost středů obou štěrbin nebo obou budičů.
param-tank_lamp_height = Výška lampy
    .help = Výška lampy nad vodou. Stínítko leží 0,5 m pod vanou; nižší lampa obraz víc roztáhne.
param-tank_source_speed = Rychlost budiče
    .help = Jak rychle se budič v dopplerovském uspořádání pohybuje přes vanu. Před ním se vlny zhušťují, za ním se rozestupují; je-li rychlejší než vlny (asi 0,31 m/s v 10 mm vody), zanechává příďovou vlnu ve tvaru V jako za lodí.
param-tank_strobe = Stroboskop
    .help = Osvětluje vanu záblesky tolikrát za sekundu (0: stálá lampa). Při frekvenci budičů zastihne každý záblesk vlny na stejném místě, takže obrazec stojí a dá se měřit; při frekvenci trochu odlišné vlny pomalu postupují vpřed nebo vzad.
param-tank_lines = Čáry štěrbin
    .help = Nakreslí z místa mezi štěrbinami směry, kam teorie klade obrazec: pro dvě štěrbiny světlé čáry, d sin θ = m λ (d je rozteč štěrbin); pro jednu štěrbinu tmavé, w sin θ = m λ (w je její šířka).
param-tank_beaches = Pláže
    .help = Šikmé pláže podél stěn, které vlny pohlcují (jako pěnové nebo síťové pásy ve skutečné vaně), nebo holé stěny, které je odrážejí.
param-tank_pulse = Jeden pulz
    .help = Budiče (nebo lišta) vytvoří jeden hřeben a zastaví se, pokaždé když se tato volba zapne nebo se vana resetuje, místo stálé řady vln: sledujte, jak se jediná vlna šíří, odráží a prochází štěrbinami. Všechny budiče zvednou vodu ve stejném okamžiku (fázový krok, rozladění ani vlastní fáze či frekvence budiče tvar pulzu neovlivní).
param-tank_probe = Sonda
    .help = Sonda ve vodě (kroužek) a v rohu obrazu graf její výšky za poslední čtyři sekundy; pod vanou frekvence a rozkmit, které naměří. Umístěte ji nástrojem sonda v nabídce Nástroj nebo dvěma posuvníky níže.
param-tank_probe_x = Sonda napříč
    .help = Poloha sondy napříč vanou od jejího středu, doprava při pohledu shora s lištou dole (zůstává uvnitř vany).
param-tank_probe_z = Sonda podél
    .help = Poloha sondy podél vany od jejího středu ke vzdálenější straně (zůstává uvnitř vany).
param-tank_graph = Graf intenzity
    .help = Čára přes vanu a nad ní graf intenzity podél této čáry (druhá mocnina výšky zprůměrovaná zhruba za poslední sekundu): kde se vlny sčítají a kde se ruší, jak by to ukázalo stínítko daleko od štěrbin.
param-tank_graph_z = Čára grafu
    .help = Kde čára grafu intenzity protíná vanu, od jejího středu ke vzdálenější straně (zůstává uvnitř vany).

## Vlny na pozadí

param-ambient = Vlny na pozadí
    .help = Hladina, která se pod vašimi vlnkami pohybuje sama: žádné; sinusovky (součet postupujících sinusových vln s ostrými hřebeny); módy (vlastní stojaté vlny bazénu, které jsou u každé stěny vodorovné); Gerstner (Gerstnerovy vlny: voda se pohybuje po kružnicích, hřebeny se zostřují); nebo FFT (oceán z tisíců vln podle spektra).
param-ambient-none = žádné
param-ambient-sines = sinusovky
param-ambient-modes = módy
param-ambient-gerstner = Gerstner
param-ambient-fft = FFT
param-wind_speed = Rychlost větru
    .help = Vítr Phillipsova spektra, ze kterého pocházejí amplitudy vln: silnější vítr dává větší část výšky delším vlnám.
param-wind_direction = Směr větru
    .help = Směr, kam vítr vane, od +x k +z.
param-wave_height = Výška vln
    .help = Významná výška H_s vln na pozadí: čtyřnásobek směrodatné odchylky hladiny.
param-wave_spread = Rozptyl směrů
    .help = O kolik (±) se směry postupujících vln odchylují od směru větru.
param-steepness = Strmost Q
    .help = Gerstnerova strmost: 0 dává obyčejné sinusovky; směrem k 1 se voda shromažďuje pod ostrými hřebeny (při 1 by se z nich staly hroty).
param-spectrum = Spektrum
    .help = Spektrum vln oceánu FFT: Phillips (podle Tessendorfa) nebo JONSWAP (naměřená moře s omezenou délkou rozběhu větru, ostřejší vrchol; zde rozběh 100 m).
param-spectrum-phillips = Phillips
param-spectrum-jonswap = JONSWAP
param-fft_size = Mřížka FFT
    .help = Počet vln na stranu mřížky oceánu FFT: 128 přidá vlnky až do 6 cm.
param-choppiness = Rozbouřenost
    .help = Voda oceánu FFT se pohybuje i do stran a shromažďuje se pod hřebeny (Tessendorfovy „choppy“ vlny); 0 je samotné výškové pole.

## Optika

param-fresnel = Fresnelův model
    .help = Jakou část světla hladina odráží pod každým úhlem: přesný (přesné Fresnelovy rovnice), tabulka (totéž z vyhledávací textury), Schlick (Schlickova aproximace), inverzní mocnina (1/(1+cos θ)^8), omezená mocnina (clamp((1-cos θ)^4, 0.05, 0.3)) nebo lineární (1-cos θ).
param-fresnel-exact = přesný
param-fresnel-table = tabulka
param-fresnel-schlick = Schlick
param-fresnel-inverse_power = inverzní mocnina
param-fresnel-clamped_power = omezená mocnina
param-fresnel-linear = lineární
param-specular = Odlesk slunce
    .help = Tvar odlesku slunce na vodě: Phong (odražený paprsek vůči slunci) nebo Blinn-Phong (normála vůči polovičnímu vektoru), při stejné lesklosti širší.
param-specular-phong = Phong
param-specular-blinn_phong = Blinn-Phong
param-shininess = Lesklost
    .help = Exponent s v cos^s odlesku: vyšší dává menší a ostřejší odlesk.
param-dispersion = Disperze
    .help = Červené a modré světlo se lámou podle svých vlastních indexů lomu (voda: 1,331 červené, 1,335 zelené, 1,337 modré), s tolikrát větším rozdílem než ve skutečnosti: barevné lemy na okrajích kaustik a na okraji Snellova okna. 0: vypnuto.

## Barva vody

param-absorption_red = Absorpce, červená
    .help = Absorpce červeného světla na metr vody podle Beerova–Lambertova zákona: po d metrech ho zbývá exp(-a d).
param-absorption_green = Absorpce, zelená
    .help = Absorpce zeleného světla na metr vody podle Beerova–Lambertova zákona: po d metrech ho zbývá exp(-a d).
param-absorption_blue = Absorpce, modrá
    .help = Absorpce modrého světla na metr vody podle Beerova–Lambertova zákona: po d metrech ho zbývá exp(-a d).
param-scatter_red = Rozptýlené světlo, červená
    .help = Světlo, které voda sama rozptyluje k vám (červená, lineární jednotky; obloha má asi 0,5): doplňuje to, co pohltí absorpce, takže hluboká voda dostane tuto barvu místo černé. 0 ve všech kanálech: vypnuto.
param-scatter_green = Rozptýlené světlo, zelená
    .help = Světlo, které voda sama rozptyluje k vám (zelená, lineární jednotky; obloha má asi 0,5): doplňuje to, co pohltí absorpce, takže hluboká voda dostane tuto barvu místo černé. 0 ve všech kanálech: vypnuto.
param-scatter_blue = Rozptýlené světlo, modrá
    .help = Světlo, které voda sama rozptyluje k vám (modrá, lineární jednotky; obloha má asi 0,5): doplňuje to, co pohltí absorpce, takže hluboká voda dostane tuto barvu místo černé. 0 ve všech kanálech: vypnuto.
param-view_colour = Barva podle úhlu pohledu
    .help = Rozptýlené světlo ztrácí polovinu zelené při šikmém pohledu podél hladiny a zachovává si ji při pohledu přímo dolů, jako když hry tónují vodu podle úhlu pohledu (vyžaduje rozptýlené světlo).

## Simulace

param-sim_size = Rozlišení mřížky
    .help = Počet buněk na stranu simulační mřížky; změna vodu převzorkuje, neresetuje ji.
param-paused = Pozastaveno
    .help = Zmrazí vodu (mezerník).

## Ladění

param-debug_view = Ladicí zobrazení
    .help = Ukazuje jednu z textur simulace: výšku (červená nahoru, modrá dolů), normály hladiny, svislou rychlost nebo mapu kaustik; nebo Fresnelovu odrazivost vody v odstínech šedi (černá 0, bílá 1); nebo spektrum vln na pozadí (amplituda pro každý vlnový vektor, logaritmická stupnice, k = 0 uprostřed, kruhy u vlnových délek 0,9 m a 0,2 m).
param-debug_view-off = vypnuto
param-debug_view-height = výška
param-debug_view-normals = normály
param-debug_view-velocity = rychlost
param-debug_view-caustics = kaustiky
param-debug_view-reflectance = odrazivost
param-debug_view-spectrum = spektrum
param-debug_inset = Ladicí zobrazení v rohu
    .help = Ukazuje ladicí zobrazení v rohu scény (zapnuto) nebo přes celou scénu (vypnuto).

## Zobrazení

param-quality = Rozlišení
    .help = Měřítko rozlišení scény: pevné, nebo auto (snižuje se po krocích až na 50 %, dokud snímky trvají déle, než dovoluje čas na snímek, a znovu se zvyšuje, když je rezerva).
param-quality-auto = auto
param-frame_budget = Čas na snímek
    .help = Nejdelší doba, kterou by měl snímek trvat; při automatickém rozlišení pomalejší snímky rozlišení sníží.

## Plochá voda

param-render_mode = Vykreslení vody
    .help = Jak se kreslí vodní hladina. raytracing: každý pixel hladiny sleduje své odražené a lomené paprsky bazénem. plochá: technika, kterou používají hry: scéna se kreslí ještě dvakrát do textur, zrcadlená v rovině vody (odraz) a oříznutá pod ní (lom), a plochá rovina je mísí podle Fresnela, rozvlněná zkreslením místo ohybu vlnami. Je to technika pro pohled nad vodou: pod vodou kreslí raytracing. rozdělené: vlevo plochá, vpravo raytracing, s dělicí čarou, kterou lze táhnout.
param-render_mode-raytraced = raytracing
param-render_mode-flat = plochá
param-render_mode-split = rozdělené
param-split = Dělicí čára
    .help = Kde dělicí čára stojí, jako podíl šířky zleva: vlevo od ní plochá voda, vpravo raytracing. Přesunete ji tažením na plátně.
param-flat_distortion = Zkreslení
    .help = Co rozvlní odraz a lom ploché vody: dudv, opakující se mapa zkreslení (mapa dUdV) posouvaná v čase (kliknutí v ní nevytvářejí vlnky), nebo vlnky, vlastní sklony hladiny ze simulace (stejné vlny jako u raytracingu, s napodobenou optikou).
param-flat_distortion-dudv = dudv
param-flat_distortion-ripples = vlnky
param-flat_strength = Síla zkreslení
    .help = Jak daleko zkreslení posune textury odrazu a lomu, jako podíl obrazovky. Neroste se vzdáleností k tomu, co je vidět, jako skutečný lom: okraj vysoko nad vodou se vlní stejně jako dlaždice pod ní.
param-dudv_speed = Rychlost zkreslení
    .help = Počet dlaždic mapy dudv posunutých za simulovanou sekundu (zastaví se, když je voda pozastavená); platí pro zkreslení dudv.
param-flat_resolution = Rozlišení textur
    .help = Velikost textur odrazu a lomu vůči scéně: menší jsou levnější a rozmazanější.
param-flat_caustics = Kaustiky
    .help = Světlo na bazénu pod plochou vodou: vypnuto (jako pod klidnou hladinou), falešné (odlesk tam, kde by normála zkreslení poslala slunce přímo dolů; bez soustředění, bez průchodu navíc) nebo skutečné (mapa kaustik z raytracingu, jeden průchod navíc).
param-flat_caustics-off = vypnuto
param-flat_caustics-fake = falešné
param-flat_caustics-real = skutečné
param-flat_soft_edge = Měkký okraj
    .help = Voda mělčí než tato hodnota (ve směru pohledu) se zkresluje méně, což skryje šev, kde plochá rovina naráží na stěny; 0 šev ukáže.

## Vlastní nastavení každého budiče ve vaně (nadpis skupiny: „Budič“ a jeho číslo)

param-frequency = Jeho frekvence
    .help = Jak často se tento budič pohybuje nahoru a dolů. Dva budiče s trochu odlišnou frekvencí vytvářejí rázy: jejich klidné čáry přebíhají přes vanu.
param-amplitude = Jeho amplituda
    .help = Jak silně tento budič rozkmitá vodu (0 ho zastaví). Kde se vlny silného a slabého budiče potkají hřebenem s důlem, vyruší se jen zčásti.
param-phase = Jeho fáze
    .help = O kolik tento budič předbíhá nastavenou fázi (celý cyklus je 360°; záporná: zpožďuje se). Dva budiče posunuté o 180° posílají hřeben proti důlu: střední čára mezi nimi je klidná.

## Předvolby (název a text, který čte student)

preset-classic = Klasický vzhled
    .help = Jedna koule, která zůstává, kam ji položíte (G ji pustí), odrážející stěny, kaustiky: bazén tak, jak ho ukazuje klasická WebGL Water.
preset-calm = Klidná voda
    .help = V bazénu nic, malé kapky, vlny rychle doznívající u pohlcujících stěn: klidná hladina pro studium vlnek jedné po druhé.
preset-busy = Rušný bazén
    .help = Koule a kachna plovoucí na rychlé, živé vodě s velkými kapkami a odrážejícími stěnami.
preset-fresnel = Lekce: Fresnelova odrazivost
    .help = Klidná, prázdná voda viděná nízko přes bazén, takže úhel dopadu sahá od asi 50° u vás až po klouzavý dopad na vzdálené straně: přepínejte Fresnelův model a sledujte, jak se mění odraz i graf.
preset-glint = Lekce: odlesk slunce
    .help = Pohled proti nízkému slunci: táhněte po vodě, vytvořte vlny a uvidíte odlesk Blinn-Phong protažený ve směru pohledu; pro srovnání přepněte Odlesk slunce na Phong a měňte Lesklost.
preset-breeze = Lekce: vlny na pozadí
    .help = Mírný vánek žene přes bazén pod vašimi vlnkami vlny s ostrými hřebeny; přepněte Vlny na pozadí na módy a uvidíte vlastní stojaté vlny bazénu, které jsou u každé stěny vodorovné, na Gerstner pro vodu pohybující se po kružnicích, nebo na FFT pro spektrum tisíců vln (ladicí zobrazení spektrum ukazuje vlny každého modelu).
preset-ocean = Lekce: oceán FFT
    .help = Tessendorfův oceán v bazénu: Phillipsovo spektrum asi tisíce vln na mřížce 128 bodů, sečtených pomocí FFT v každém snímku; ladicí zobrazení ukazuje spektrum, protažené po směru větru.
preset-flat = Lekce: plochá voda vs. raytracing
    .help = Plochá voda z her (vlevo) proti raytracingu (vpravo), koule napůl nad vodou: táhněte dělicí čáru přes kouli. Vlevo je její ponořená polovina neohnutá ve skutečné hloubce a odrazy se vlní o pevný posun; vpravo ji voda zvedá a vše ohýbá podle sklonu vln. Vytvořte vlnky a přepněte Zkreslení na vlnky: uvidíte stejné vlny s napodobenou optikou.
preset-lake = Lekce: barva vody
    .help = Zelená jezerní voda: pohlcuje červenou, zelenou i modrou rychleji než voda v bazénu a sama rozptyluje zelenomodré světlo, takže hluboký konec zezelená místo aby ztmavl (nastavte rozptýlené světlo na 0 a uvidíte čistý Beerův–Lambertův zákon).
preset-noon = Poledne
    .help = Slunce téměř v nadhlavníku: sytě modrá obloha, krátké stíny, nejjasnější kaustiky na dně.
preset-evening = Večer
    .help = Nízké teplé slunce z boku, obraz exponovaný na něj: dlouhé stíny přes terasu, voda tmavá tam, kde ji stíní okraj, vzdálená stěna osvětlená kaustikami od slunce.
preset-sea = Lekce: otevřené moře
    .help = Otevřená voda až k obzoru za mírného větru: pět kaskád FFT s různými velikostmi dlaždic, takže se žádný vzor neopakuje; mřížka, na které se moře kreslí, se promítá z obrazovky, takže její podrobnost sleduje váš pohled; opar slévá moře a oblohu na obzoru do jedné barvy (vypněte Mlhu a uvidíte okraj moře); ostrov před vámi stojí v tyrkysových mělčinách s pěnou podél břehu a zrcadlí se ve vodě (zapněte Zobrazit mřížku a uvidíte mřížku). Klikněte blízko středu, vytvořte vlnky v oblasti simulované vody a sledujte, jak se šíří ven; gumová kachnička tam, zvětšená tolikrát, kolikrát je oblast větší než bazén, se houpe na vlnách a zanechává brázdu: táhněte ji a uvidíte ji.
preset-shore = Lekce: vlnky na mělčině
    .help = Pláž ostrova u oblasti simulované vody, za slabého vánku pod vysokým sluncem: sklony vln soustředí sluneční světlo do sítě kaustik na písku několik metrů pod hladinou. Klikněte do vody a vytvořte vlnky: kde je správná hloubka, jejich kruhy se soustředí do světlých čar na dně, které je ukazují mnohem lépe než samotná hladina. Houpající se kachna kreslí vlastní kruhy a její stín leží na písku.
preset-dawn = Klidné moře za úsvitu
    .help = Nízké slunce před vámi nad klidným mořem: jeho odlesk rozprostřený do dlouhé třpytivé cesty po malých vlnách, obloha podél obzoru teplá.
preset-storm = Bouře na moři
    .help = Silný vítr zvedá 5m vlny se zostřenými hřebeny pod nízkým sluncem, v hustém oparu; kachnou zmítají vlny s bílými čepicemi.
preset-tank = Vlnová vana: jeden budič
    .help = Školní vlnová vana při pohledu shora: budič uprostřed vany s vodou hlubokou 10 mm kmitá desetkrát za sekundu a lampa nad vanou vrhá jeho kruhy na stínítko pod ní jako světlé kružnice, protože každý hřeben soustředí světlo jako čočka. Přepněte Zobrazení na výšky a uvidíte samotné vlny; měňte Frekvenci a sledujte, jak se kruhy zhušťují (vlnová délka je rychlost dělená frekvencí).
preset-single_slit = Vlnová vana: jedna štěrbina
    .help = Rovná lišta vytváří rovinné vlny, které narazí na překážku s jednou mezerou. Za mezerou se rozbíhají do vějíře; čím užší je mezera vůči vlnové délce, tím širší vějíř (vyzkoušejte Šířku štěrbiny).
preset-double_slit = Vlnová vana: dvě štěrbiny
    .help = Rovinné vlny procházejí dvěma mezerami vzdálenými 90 mm: vlny z obou mezer se kříží, a kde se hřeben potká s hřebenem, ukazuje stínítko světlé čáry, zatímco mezi nimi, kde se hřeben potká s důlem, zůstává voda klidná. Klidné čáry se rozbíhají pod úhly, kde se dráhy liší o polovinu vlnové délky; přepněte Zobrazení na intenzitu a uvidíte je.
preset-refraction = Vlnová vana: lom
    .help = Rovinné vlny narážejí na skleněnou destičku pod vodou. Voda nad ní je mělčí, takže vlny zpomalí a přiblíží se k sobě, a kde přecházejí přes šikmý okraj destičky, ohnou se: Snellův zákon pro vlny na vodě.
preset-lens = Vlnová vana: čočka
    .help = Skleněná destička ve tvaru čočky pod vodou: vlny nad ní zpomalí a střed každé vlnoplochy stráví nad destičkou nejdéle, takže rovné vlnoplochy vyjdou zakřivené a sejdou se v ohnisku za ní, jako světlo za skleněnou čočkou.
preset-doppler = Vlnová vana: pohybující se zdroj
    .help = Budič se pohybuje přes vanu rychlostí 0,12 m/s, asi 40 % rychlosti vln: před ním se hřebeny zhušťují, za ním se rozestupují, tak jako tón projíždějící sirény stoupá a klesá. Zvyšte jeho rychlost nad rychlost vln (asi 0,31 m/s) a předběhne vlastní vlny: vznikne příďová vlna.
preset-reflection = Vlnová vana: duté zrcadlo
    .help = Rovné vlny narážejí na zakřivenou stěnu ve tvaru paraboly. Každá část stěny je vrací pod svým vlastním úhlem a všechny se sejdou v jednom bodě před ní, v ohnisku, jako světlo v zrcadle baterky nebo v satelitní anténě. Přepněte Zobrazení na intenzitu a uvidíte světlé ohnisko.
preset-standing = Vlnová vana: stojaté vlny
    .help = Rovné vlny narážejí na rovnou stěnu a vracejí se samy sebou zpět. Kde se potkají, skládají se do stojatých vln: čáry klidné vody (uzly) vzdálené od sebe polovinu vlnové délky a mezi nimi voda, která se pohybuje nahoru a dolů, aniž by někam postupovala. Přepněte Zobrazení na výšky a nastavte Stroboskop na frekvenci budičů.
preset-phased_array = Vlnová vana: fázované pole
    .help = Čtyři budiče v řadě, 30 mm od sebe (o něco víc než polovina vlnové délky při 6 Hz), každý o čtvrtinu cyklu za předchozím. Jejich vlny se sčítají jen v jednom směru, ve svazku stočeném asi o 25° ke zpožděnému konci: měňte Fázový krok a svazek se natočí, aniž by se cokoli pohnulo, tak jako fázovaný radar nebo ultrazvuková sonda směruje svůj svazek. Přepněte Zobrazení na intenzitu a uvidíte svazek.
