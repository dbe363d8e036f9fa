# Reči programa wavepool na srpskom (ćirilica; latinica u sr-Latn.ftl, preslovljena), prevod izvornog kataloga en.ftl (Project Fluent,
# https://projectfluent.org/fluent/guide/). Jezik se dodaje tako što se ovaj fajl kopira u
# locales/<tag>.ftl, prevede tekst svake poruke (nikad njen identifikator ni njene { $variables }) i
# oznaka jezika upiše u web/i18n.js (LANGUAGES). Simboli jedinica (m/s, Hz, °) i vlastita imena
# ostaju kako jesu.

## Reči same stranice (web/*.js)

language = Jezik
controls = Kontrole
preset = Postavka
    .title = Počni iznova od podešavanja i pogleda lekcije
preset-choose = izaberite…
preset-applied = Primenjena je postavka { $name }.
preset-press-enter = Pritisnite Enter da primenite postavku { $name }.
reset = Resetuj
    .title = Vraća stranicu na početak: njene parametre i pogled, mirnu vodu, predmete na njihovim mestima
defaults = Podrazumevano
    .title = Vraća svaki parametar na podrazumevanu vrednost
share-link = Podeli vezu
    .title = Kopira vezu koja otvara ovaj bazen sa ovim parametrima i ovim pogledom
embed-code = Kopiraj kod za umetanje
    .title = Kopira <iframe> koji prikazuje ovaj bazen, kakav je sada, na drugoj stranici
link-copied = Veza je kopirana.
embed-code-copied = Kod za umetanje je kopiran.
embed-title = Interaktivni bazen sa vodom (wavepool)
fullscreen = Ceo ekran
    .title = Ceo ekran (izlaz tasterom Esc)
play = Pokreni
    .title = Pokreni: voda i predmeti se pokreću
pause = Pauza
    .title = Pauza: voda i predmeti se zaustavljaju
on = uključeno
off = isključeno
dipper = Izvor { $number }
notice-no-gpu = Ovaj pregledač crta bez GPU-a, pa su najveće veličine smanjene da bi odziv ostao brz: { $sizes }.
notice-slow-resolution = Kadrovi su ovde trajali duže od sekunde: rezolucija je sada automatska.
notice-slow-grid = Kadrovi su ovde trajali duže od sekunde: mreža simulacije je smanjena na { $cells } ćelija.
fresnel-plot = Refleksija u zavisnosti od upadnog ugla: izabrani Frenelov model preko tačne krive
fresnel-angle = upadni ugao
fresnel-caption = Refleksivnost: izabrani model (plavo) preko tačnog (sivo); iz vazduha puna linija, ispod vode isprekidana; | vaš pogled
status-loading = Učitavam vodu…
status-device-lost = Grafički uređaj je izgubljen; ponovo pokrećem…
status-waiting = Čekam slobodan GPU kontekst: skrolujte drugu demonstraciju vode na ovoj stranici van vidokruga.
page-intro = Kliknite ili prevucite po vodi da napravite talasiće, prevucite plutajući predmet da ga pomerite, prevucite drugde da okrenete kameru; točkićem ili štipanjem zumirajte. Kad je demo u fokusu: razmak pauzira, G ispušta predmete, L stavlja sunce iza vas.
page-starting = Pokrećem vodu…
page-running = Radi na { $api }, { $adapter }.
page-running-unnamed = Radi na { $api } (pregledač ne kaže na kom GPU-u).
page-failed = Voda ovde nije mogla da se pokrene: okvir ispod kaže zašto.
error-backend-forced = Ova stranica je tražila samo { $api } (backend={ $backend }), a ovaj pregledač nije uspeo da ga pokrene:
error-backend-forced-fix = Uklonite backend={ $backend } iz adrese ili opcija (ili postavite backend=auto) da bi demo izabrao interfejs koji ovaj pregledač ima.
error-no-backend = Ovaj pregledač nije uspeo da pokrene demo sa vodom: nisu radili ni WebGPU ni WebGL2 (grafičko ubrzanje je možda isključeno u njegovim podešavanjima).
error-no-webgpu = WebGPU: ovaj pregledač ga ne nudi (nedostaje navigator.gpu)
error-stopped = Demo sa vodom se zaustavio: { $reason }
error-device-lost = Grafički uređaj je izgubljen i nije mogao ponovo da se pokrene: { $reason }
error-crashed = Demo sa vodom se srušio: { $reason }
error-restart = Demo sa vodom nije mogao ponovo da se pokrene: { $reason }
fallback-picture = Nepomična slika bazena (živi demo ovde nije mogao da se pokrene)
canvas-label = Bazen sa vodom. Prevucite po vodi da napravite talasiće, prevucite kuglu da je pomerite, prevucite drugde da okrenete kameru. Tasteri: strelice okreću, + i - zumiraju, Enter pušta kap u sredinu, razmak pauzira, G gravitacija, L svetlo.
costs-gpu = GPU vreme za crtanje vode: { $times }.
costs-no-gpu-time = GPU vreme: ovaj pregledač ga ne meri (nema WebGPU vremenskih oznaka).
costs-between = Između kadrova: { $times }.
note-flat-under-water = Ravna voda je tehnika za pogled iznad vode: pod vodom crta praćenje zraka.
reading-probe-frequency = Frekvencija sonde
reading-probe-swing = Otklon sonde
reading-ruler = Lenjir
viewer-reset-water = Umiri vodu
    .title = Poravnaj vodu i vrati kuglu na mesto
viewer-frame = kadar: { $cpu } ms CPU, { $between } ms između kadrova
viewer-gpu = GPU: { $stages }
viewer-gpu-none = GPU vreme: ovaj uređaj nema upite vremenskih oznaka
viewer-gpu-waiting = GPU vreme: čekam prve vremenske oznake
viewer-costs = crtanje vode (kaustike + senčenje): { $costs }
viewer-water = voda: { $cells }² ćelija, { $seconds } s simulirano
viewer-adapter = adapter: { $name }
stage-simulation = simulacija
stage-caustics = kaustike
stage-maps = mape
stage-screen = ekran
stage-shading = senčenje
stage-the-tank = kada
stage-waves = talasi
viewer-reset-one = vrati
    .title = Vrati podrazumevanu vrednost

## The parameter table and the presets
## (piše ih `wavepool messages` iz tabela u src/: engleski tekst se menja tamo)

group-water = Voda
group-drops = Kapi
group-light = Svetlost
group-scene = Scena
group-objects = Predmeti
group-tank = Kada
group-ambient-waves = Pozadinski talasi
group-optics = Optika
group-water-colour = Boja vode
group-simulation = Simulacija
group-debug = Dijagnostika
group-display = Prikaz
group-flat-water = Ravna voda
unit-cells = ćelija

## Voda

param-wave_speed = Brzina talasa
    .help = Brzina c talasića u talasnoj jednačini h_tt = c² ∇²h.
param-damping = Prigušenje
    .help = Brzina k kojom talasi gube energiju (amplituda opada kao exp(-k t / 2)).
param-absorbing_walls = Upijajući zidovi
    .help = Zidovi gutaju talase u prigušnom sloju duž sebe umesto da ih odbijaju.
param-foam = Pena
    .help = Bela voda tamo gde bregovi padaju ubrzanjem većim od četvrtine g, gde voda zapljuskuje zid i gde kapi i tela razbacuju vodu; pena bledi i širi se.
param-foam_decay = Trajanje pene
    .help = Vremenska konstanta tau nestajanja pene: posle tau sekundi ostaje 37 % pene.

## Kapi

param-drop_radius = Poluprečnik kapi
    .help = Poluprečnik kosinusne izbočine koju dodaje klik ili prevlačenje.
param-drop_strength = Jačina kapi
    .help = Visina izbočine u njenom središtu (negativna potiskuje vodu naniže).
param-start_drops = Kapi na početku
    .help = Kapi koje padnu u bazen kada se stranica otvori, da se njihovi krugovi i kaustike koje bacaju vide odmah (0: voda počinje mirna).

## Svetlost

param-sun_azimuth = Azimut sunca
    .help = Pravac sunca oko bazena, po kompasu.
param-sun_elevation = Visina sunca
    .help = Visina sunca iznad horizonta.
param-sun_size = Veličina sunca
    .help = Ugaoni prečnik sunčevog diska na nebu i u njegovim odrazima (pravo sunce: 0,5°).
param-exposure = Ekspozicija
    .help = Osvetljenost slike u fotografskim stepenima ekspozicije (svaki +1 udvostručuje svetlost pre filmske tonske krive), povrh ekspozicije same kamere: niže sunce se eksponira za svetlost koju gubi.
param-setting = Okruženje
    .help = Gde je bazen: ukopan u popločanu terasu pod nebom ili u klasičnoj kutiji u preseku, otvorenoj na bližim zidovima, tako da se vidi poprečni presek vode.
param-setting-deck = terasa
param-setting-cutaway = presek
param-caustics = Kaustike
    .help = Svetlost koju talasi fokusiraju na dno, zidove i kuglu.
param-caustic_contrast = Kontrast kaustika
    .help = Koliko se kaustične linije ističu: fokusirana svetlost podignuta na ovaj stepen. 1 je svetlost koju simulirani talasi fokusiraju, kako je drži mapa kaustika (razmazana preko njenih teksela, pa su linije šire i bledije nego što bi ih sunce nacrtalo); 2 im vraća sjaj mreže u bazenu na suncu.
param-tile_gloss = Sjaj pločica
    .help = Koliko glazura pločica odslikava okolinu: 1 keramička glazura (nebo i sunčev odsjaj na pločicama iznad vode, najviše na njihovim zaobljenim ivicama), 0 mat pločice.

## Scena

param-scene = Scena
    .help = Bazen, otvoreno more do horizonta pod istim nebom ili talasna kada iz školske laboratorije, sa lampom i ekranom.
param-scene-pool = bazen
param-scene-sea = more
param-scene-tank = kada
param-sea_wind = Vetar
    .help = Brzina vetra nad morem: jači vetar prenosi energiju talasa na veće talasne dužine.
param-sea_wind_direction = Smer vetra
    .help = Smer u kome vetar duva, od +x ka +z.
param-sea_wave_height = Visina talasa
    .help = Značajna visina talasa: četiri standardne devijacije visine mora (otprilike srednja visina najviše trećine talasa).
param-sea_choppiness = Uzburkanost
    .help = Koliko se voda pomera u stranu ka bregovima i tako ih izoštrava (Tessendorf-ova lambda).
param-sea_fog = Magla
    .help = Izmaglica nad morem, sve ređa s visinom, koja na horizontu izjednačava boju vode i neba.
param-sea_fog_distance = Domet magle
    .help = Rastojanje na kome izmaglica na nivou mora priguši svetlost na 37 %.
param-sea_island = Ostrvo
    .help = Ostrvo s plažama, koje se vidi kroz plićak oko njega, gde se talasi pene duž obale: na pučini u izmaglici ili uz obalu, s plićakom ispod polja gde klikovi prave talasiće, a kaustike tih talasića osvetljavaju pesak.
param-sea_island-none = nema
param-sea_island-offshore = na pučini
param-sea_island-shore = uz obalu
param-sea_grid = Prikaži mrežu
    .help = Ocrtava ćelije mreže na kojoj se crta more: postavljena je preko ekrana i projektovana na vodu, pa joj ćelije na ekranu ostaju približno iste veličine, male blizu vas i izdužene ka horizontu.

## Predmeti

param-sea_objects = Predmeti
    .help = Šta pluta na moru: kugla, patka i lopta za plažu iz bazena, onoliko veće koliko je polje simulirane vode veće od bazena. Ljuljaju se na talasima i ostavljaju brazde u tom polju.
param-sea_objects-none = ništa
param-sea_objects-sphere = kugla
param-sea_objects-duck = patka
param-sea_objects-both = obe
param-sea_objects-ball = lopta
param-sea_objects-all = sve
param-objects = Predmeti
    .help = Šta pluta u bazenu: bilo šta od kugle, gumene patke i lopte za plažu (kao spisak, npr. sphere,duck), sve ili ništa.
param-objects-none = ništa
param-objects-sphere = kugla
param-objects-duck = patka
param-objects-both = obe
param-objects-ball = lopta
param-objects-all = sve
param-sphere_radius = Poluprečnik kugle
    .help = Poluprečnik kugle.
param-sphere_density = Gustina kugle
    .help = Masa po jedinici zapremine; ako je manja od 1000 kg/m³, koliko ima voda, kugla pluta.
param-duck_density = Gustina patke
    .help = Masa po jedinici zapremine gumene patke: što je lakša, to više viri iz vode.
param-ball_radius = Poluprečnik lopte
    .help = Poluprečnik lopte za plažu.
param-ball_density = Gustina lopte
    .help = Masa po jedinici zapremine lopte za plažu (vazduh u tankoj ljusci, s malo peska unutra da se manje ljulja): laka je, pa pluta visoko na vodi.
param-gravity = Gravitacija
    .help = Predmeti padaju, plutaju, ljuljaju se i plove na talasima (taster G); kad je isključena, ostaju gde su postavljeni.

## Kada

param-tank_setup = Ogled
    .help = Šta je u kadi: jedan izvor, dva izvora, prava šipka koja pravi ravne talase, šipka iza pregrade s jednim ili dva proreza, šipka i staklena ploča čija prava ivica skreće talase (prelamanje), ploča u obliku sočiva koja ih skuplja u žižu, izvor koji se kreće kroz kadu (Doppler), zakrivljeni zid koji odbija talase šipke u žižu (parabolično ogledalo), prav zid naspram šipke (stojeći talasi) ili staklena prizma koja skreće talase šipke u stranu.
param-tank_setup-dipper = jedan izvor
param-tank_setup-two_dippers = dva izvora
param-tank_setup-plane_wave = ravan talas
param-tank_setup-single_slit = jedan prorez
param-tank_setup-double_slit = dva proreza
param-tank_setup-refraction = prelamanje
param-tank_setup-lens = sočivo
param-tank_setup-doppler = pokretni izvor
param-tank_setup-reflection = odbijanje
param-tank_setup-standing = stojeći talasi
param-tank_setup-prism = prizma
param-tank_look = Izgled
    .help = Prikaz „ekran“ pokazuje papir ispod kade odozgo, onako kako ga gleda razred; „aparatura“ pokazuje laboratorijsku kadu u 3D: lampu iznad posude, vodu, ram na nogarima i papir na stolu ispod, s likom lampe na njemu (prevlačenjem obilazite oko nje); „podela“ prikazuje oba jedno pored drugog.
param-tank_look-screen = ekran
param-tank_look-apparatus = aparatura
param-tank_look-split = podela
param-tank_view = Prikaz
    .help = Šta slika prikazuje: svetlost lampe na ekranu ispod kade (svaki breg je fokusira kao sočivo u svetlu liniju), visinu vode kao boju ili intenzitet: kvadrat visine, usrednjen tokom otprilike poslednje sekunde.
param-tank_view-screen = ekran
param-tank_view-heights = visine
param-tank_view-intensity = intenzitet
param-tank_tool = Pokazivač
    .help = Šta radi klik ili prevlačenje po posudi: spušta male impulse u vodu, crta prave zidove koje talasi ne mogu da pređu, od mesta gde pritisnete do mesta gde pustite (sopstvena pregrada, reflektor, kutija), briše ih nazad u otvorenu vodu, postavlja sondu gde kliknete, polaže lenjir od mesta gde pritisnete do mesta gde pustite (njegova dužina se prikazuje ispod kade: položite ga preko deset bregova da izmerite talasnu dužinu) ili pomera izvor ili šipku: pritisnite ga i prevucite (izvor koji pritisnete tada prikazuje svoju frekvenciju, amplitudu i fazu).
param-tank_tool-drops = kapi
param-tank_tool-walls = zidovi
param-tank_tool-erase = brisanje
param-tank_tool-probe = sonda
param-tank_tool-ruler = lenjir
param-tank_tool-move = pomeranje
param-tank_frequency = Frekvencija
    .help = Koliko često se izvori (ili šipka) podižu i spuštaju. Talasna dužina je brzina podeljena frekvencijom.
param-tank_amplitude = Amplituda
    .help = Koliko izvori podižu i spuštaju vodu. Dovoljan je delić milimetra: svaki breg tada fokusira svetlost lampe blizu ekrana, kao u dobro podešenoj laboratorijskoj kadi; viši talasi je fokusiraju iznad ekrana, i linije se na ekranu raspadaju.
param-tank_dippers = Broj izvora
    .help = Koliko izvora stoji u nizu u ogledu sa dva izvora, jedan od drugog udaljenih za razmak proreza.
param-tank_phase = Fazni korak
    .help = Koliko svaki izvor u nizu kasni za susedom (ceo ciklus je 360°). Talasi se sabiraju tamo gde razlika puteva nadoknađuje kašnjenje: snop se okreće ka kraju koji kasni, po sin θ = (step/360°) λ / spacing. Tako radar sa faziranim nizom ili ultrazvučna sonda usmerava snop bez pomeranja.
param-tank_detune = Razdešenost
    .help = Koliko je svaki izvor u nizu brži od prethodnog. Dva izvora tada stvaraju udare: gde su im se talasi sretali breg uz breg, uskoro se susreću breg uz dol, a mirne linije prelaze preko posude toliko puta u sekundi; niz od četiri izvora pomera svoj snop.
param-tank_amplitude_ratio = Odnos amplituda
    .help = Koliko svaki izvor u nizu pomera vodu, kao deo amplitude prethodnog. Kod dva izvora nejednake jačine mirne linije više nisu mirne: gde se breg susreće s dolom, talasi se poništavaju samo delimično.
param-tank_depth = Dubina vode
    .help = Dubina vode. Ovde talasi putuju brzinom talasa u plitkoj vodi sqrt(g d), brže u dubljoj vodi; iznad staklene ploče voda je plića, pa se talasi tu usporavaju i skreću. (Centimetarski talasići u pravoj kadi nisu dugi u odnosu na dubinu, a na njih deluje i površinski napon, pa su sporiji i brzina im zavisi od talasne dužine; ovi nisu takvi. Svaka lekcija koristi jednu frekvenciju, a ono što pokazuje zavisi samo od talasnih dužina, pa i dalje važi.)
param-tank_size = Veličina posude
    .help = Stranica kvadratne posude.
param-tank_slit_width = Širina proreza
    .help = Širina svakog otvora u pregradi.
param-tank_slit_spacing = Razmak proreza
    .help = Rastojanje između središta dva proreza ili između dva izvora.
param-tank_lamp_height = Visina lampe
    .help = Visina lampe iznad vode. Ekran je 0,5 m ispod posude; niža lampa daje širi lik.
param-tank_source_speed = Brzina izvora
    .help = Koliko brzo se izvor u ogledu „pokretni izvor“ kreće kroz kadu. Ispred njega se talasi zbijaju, iza njega se razmiču; ako je brži od talasa (oko 0,31 m/s u 10 mm vode), ostavlja pramčani talas, oblika slova V, kao iza čamca.
param-tank_strobe = Stroboskop
    .help = Osvetljava kadu bljeskovima toliko puta u sekundi (0: stalna lampa). Na frekvenciji izvora svaki bljesak zatiče talase na istom mestu, pa slika miruje i može da se meri; malo izvan te frekvencije talasi polako puze napred ili nazad.
param-tank_lines = Linije proreza
    .help = Crta, iz sredine između proreza, pravce u kojima teorija predviđa sliku: za dva proreza svetle linije, d sin θ = m λ (d je razmak proreza); za jedan prorez tamne, w sin θ = m λ (w je njegova širina).
param-tank_beaches = Plaže
    .help = Kose plaže duž zidova koje gutaju talase (kao trake od pene ili mrežice u pravoj kadi) ili goli zidovi koji ih odbijaju.
param-tank_pulse = Jedan impuls
    .help = Izvori (ili šipka) naprave jedan breg i stanu, svaki put kad se ovo uključi ili kad se kada resetuje, umesto stalnog niza talasa: posmatrajte kako se jedan talas širi, odbija i prolazi kroz proreze. Svi izvori podižu vodu u istom trenutku (fazni korak, razdešenost ili sopstvena faza ili frekvencija izvora ne utiču na oblik impulsa).
param-tank_probe = Sonda
    .help = Sonda u vodi (prsten) i grafik njene visine u poslednje četiri sekunde u uglu slike; ispod kade, frekvencija i razmah koje očitava. Postavite je alatkom „sonda“ Pokazivača ili pomoću dva klizača ispod.
param-tank_probe_x = Sonda popreko
    .help = Položaj sonde popreko posude, od sredine, udesno gledano odozgo kad je šipka dole (ostaje unutar posude).
param-tank_probe_z = Sonda uzduž
    .help = Položaj sonde duž posude, od sredine ka daljoj strani (ostaje unutar posude).
param-tank_graph = Grafik intenziteta
    .help = Linija preko posude i iznad nje grafik intenziteta duž te linije (kvadrat visine, usrednjen tokom otprilike poslednje sekunde): gde se talasi sabiraju, a gde poništavaju, kao što bi pokazao ekran daleko od proreza.
param-tank_graph_z = Linija grafika
    .help = Gde linija grafika intenziteta seče posudu, od sredine ka daljoj strani (ostaje unutar posude).

## Pozadinski talasi

param-ambient = Pozadinski talasi
    .help = Površina koja se sama kreće ispod vaših talasića: nema, zbir putujućih sinusoida oštrih bregova, sopstveni stojeći talasi bazena (modovi) koji svaki zid susreću vodoravno, Gerstner talasi (voda se kreće u krugovima, bregovi se izoštravaju) ili FFT okean (hiljade talasa iz spektra).
param-ambient-none = nema
param-ambient-sines = sinusoide
param-ambient-modes = modovi
param-ambient-gerstner = gerstner
param-ambient-fft = fft
param-wind_speed = Brzina vetra
    .help = Vetar Phillips spektra iz koga potiču amplitude talasa: jači vetar daje dužim talasima veći deo visine.
param-wind_direction = Smer vetra
    .help = Smer u kome vetar duva, od +x ka +z.
param-wave_height = Visina talasa
    .help = Značajna visina H_s pozadinskih talasa: četiri standardne devijacije visine površine.
param-wave_spread = Rasipanje pravaca
    .help = Koliko (±) pravci putujućih talasa odstupaju od pravca vetra.
param-steepness = Strmina Q
    .help = Gerstner strmina: 0 daje obične sinusoide; što je bliže 1, voda se više skuplja ispod oštrih bregova (pri 1 bi bregovi postali šiljci).
param-spectrum = Spektar
    .help = Talasni spektar FFT okeana: Phillips (po Tessendorf-u) ili JONSWAP (izmerena mora na kojima vetar deluje na ograničenoj dužini, oštriji vrh; ovde na 100 m).
param-spectrum-phillips = phillips
param-spectrum-jonswap = jonswap
param-fft_size = FFT mreža
    .help = Broj talasa po stranici rešetke FFT okeana: 128 dodaje talasiće do 6 cm.
param-choppiness = Uzburkanost
    .help = Voda FFT okeana se kreće i u stranu i skuplja se ispod bregova (Tessendorf-ovi uzburkani talasi); 0 je samo polje visina.

## Optika

param-fresnel = Fresnel-ov model
    .help = Koliki deo svetlosti površina odbija pod svakim uglom: tačne Fresnel-ove jednačine, isto to iz tabele u teksturi, Schlick-ova aproksimacija, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) ili 1-cos θ.
param-fresnel-exact = tačan
param-fresnel-table = tabela
param-fresnel-schlick = schlick
param-fresnel-inverse_power = inverzni stepen
param-fresnel-clamped_power = ograničeni stepen
param-fresnel-linear = linearan
param-specular = Sunčev odsjaj
    .help = Oblik sunčevog odsjaja na vodi: Phong (odbijeni zrak prema suncu) ili Blinn-Phong (normala prema poluvektoru), širi pri istoj sjajnosti.
param-specular-phong = phong
param-specular-blinn_phong = blinn-phong
param-shininess = Sjajnost
    .help = Eksponent s u cos^s odsjaja: veći daje manji, oštriji odsjaj.
param-dispersion = Disperzija
    .help = Crvena i plava svetlost se prelamaju svaka prema svom indeksu prelamanja (voda: 1,331 crvena, 1,335 zelena, 1,337 plava), uz rasipanje ovoliko puta veće od stvarnog: obojeni rubovi na ivicama kaustika i na obodu Snell-ovog prozora. 0: isključeno.

## Boja vode

param-absorption_red = Apsorpcija, crvena
    .help = Beer-Lambert-ova apsorpcija crvene svetlosti po metru vode: posle d metara od nje ostaje exp(-a d).
param-absorption_green = Apsorpcija, zelena
    .help = Beer-Lambert-ova apsorpcija zelene svetlosti po metru vode: posle d metara od nje ostaje exp(-a d).
param-absorption_blue = Apsorpcija, plava
    .help = Beer-Lambert-ova apsorpcija plave svetlosti po metru vode: posle d metara od nje ostaje exp(-a d).
param-scatter_red = Rasejana svetlost, crvena
    .help = Svetlost koju sama voda rasejava ka vama (crvena, u linearnim jedinicama; nebo je oko 0,5): nadoknađuje ono što apsorpcija odnese, pa duboka voda dobija ovu boju umesto da bude crna. 0 u svakom kanalu: isključeno.
param-scatter_green = Rasejana svetlost, zelena
    .help = Svetlost koju sama voda rasejava ka vama (zelena, u linearnim jedinicama; nebo je oko 0,5): nadoknađuje ono što apsorpcija odnese, pa duboka voda dobija ovu boju umesto da bude crna. 0 u svakom kanalu: isključeno.
param-scatter_blue = Rasejana svetlost, plava
    .help = Svetlost koju sama voda rasejava ka vama (plava, u linearnim jedinicama; nebo je oko 0,5): nadoknađuje ono što apsorpcija odnese, pa duboka voda dobija ovu boju umesto da bude crna. 0 u svakom kanalu: isključeno.
param-view_colour = Boja po uglu pogleda
    .help = Rasejana svetlost gubi polovinu zelene duž kosih putanja, a zadržava je kad se gleda pravo nadole, kao što igre boje vodu prema uglu pogleda (potrebna je rasejana svetlost).

## Simulacija

param-sim_size = Rezolucija mreže
    .help = Broj ćelija po stranici mreže simulacije; promena ponovo uzorkuje vodu, ali je ne resetuje.
param-paused = Pauza
    .help = Zamrzava vodu (razmaknica).

## Dijagnostika

param-debug_view = Dijagnostika
    .help = Prikazuje jednu od tekstura simulacije: visinu (crveno gore, plavo dole), normale površine, vertikalnu brzinu ili mapu kaustika; ili Fresnel-ovu refleksivnost vode u sivim tonovima (crno 0, belo 1); ili spektar pozadinskih talasa (amplituda po talasnom vektoru, logaritamska skala, k = 0 u sredini, prstenovi na talasnim dužinama 0,9 m i 0,2 m).
param-debug_view-off = isključeno
param-debug_view-height = visina
param-debug_view-normals = normale
param-debug_view-velocity = brzina
param-debug_view-caustics = kaustike
param-debug_view-reflectance = refleksivnost
param-debug_view-spectrum = spektar
param-debug_inset = Dijagnostika u uglu
    .help = Prikazuje dijagnostiku u uglu scene (uključeno) ili preko cele scene (isključeno).

## Prikaz

param-quality = Rezolucija
    .help = Razmera rezolucije scene: fiksna ili automatska (snižava se u koracima do 50 % dok kadrovi traju duže od budžeta kadra, a ponovo se povećava kad ima rezerve).
param-quality-auto = automatska
param-frame_budget = Budžet kadra
    .help = Najduže vreme koje kadar sme da traje; uz automatsku rezoluciju, sporiji kadrovi snižavaju rezoluciju.

## Ravna voda

param-render_mode = Prikaz vode
    .help = Kako se crta površina vode. „praćenje zraka“: svaki piksel površine prati svoj odbijeni i prelomljeni zrak kroz bazen. „ravna voda“: tehnika koju koriste igre: scena se crta još dvaput u teksture, kao slika u ogledalu ravni vode (odbijanje) i odsečena ispod nje (prelamanje), a ravna površ meša te dve slike po Fresnel-u, zatalasane izobličenjem umesto da ih talasi prelamaju. To je tehnika za pogled iznad vode: ispod vode crta praćenje zraka. „podela“: ravna voda levo, praćenje zraka desno od razdelnika koji prevlačite.
param-render_mode-raytraced = praćenje zraka
param-render_mode-flat = ravna voda
param-render_mode-split = podela
param-split = Razdelnik
    .help = Gde stoji razdelnik, kao deo širine računato sleva: ravna voda levo od njega, praćenje zraka desno. Prevucite razdelnik na slici da biste ga pomerili.
param-flat_distortion = Izobličenje
    .help = Šta zatalasava odraz i prelom ravne vode: „dudv“, mapa izobličenja koja se ponavlja (dUdV mapa) i klizi s vremenom (klikovi u njoj ne prave talasiće), ili „talasići“, sopstveni nagibi simulacije (isti talasi kao kod praćenja zraka, s lažnom optikom).
param-flat_distortion-dudv = dudv
param-flat_distortion-ripples = talasići
param-flat_strength = Jačina izobličenja
    .help = Koliko izobličenje pomera teksture odraza i preloma, kao deo ekrana. Ne raste s udaljenošću do onoga što se vidi, kao što raste pravi prelom: obod visoko iznad vode njiše se koliko i pločice ispod nje.
param-dudv_speed = Brzina izobličenja
    .help = Broj ponavljanja dudv mape koje prođu u simuliranoj sekundi (staje kad je voda pauzirana); uz izobličenje „dudv“.
param-flat_resolution = Rezolucija tekstura
    .help = Veličina tekstura odraza i preloma u odnosu na scenu: manje je brže i mutnije.
param-flat_caustics = Kaustike
    .help = Svetlost na bazenu ispod ravne vode: isključene (kao kod mirne površine), lažne (odsjaj gde bi normala izobličenja poslala sunce pravo nadole; bez fokusiranja, bez dodatnog prolaza) ili prave (mapa kaustika iz praćenja zraka, jedan prolaz više).
param-flat_caustics-off = isključene
param-flat_caustics-fake = lažne
param-flat_caustics-real = prave
param-flat_soft_edge = Meka ivica
    .help = Voda plića od ove vrednosti (duž pogleda) manje se izobličava, što skriva spoj gde ravna površ dodiruje zidove; 0 prikazuje spoj.

## Podešavanja svakog izvora u kadi (naslov grupe: „Izvor“ i njegov broj)

param-frequency = Njegova frekvencija
    .help = Koliko često se ovaj izvor podiže i spušta. Dva izvora malo različitih frekvencija stvaraju udare: njihove mirne linije prelaze preko posude.
param-amplitude = Njegova amplituda
    .help = Koliko ovaj izvor pomera vodu (0 ga zaustavlja). Gde se talasi jakog i slabog izvora sretnu breg uz dol, poništavaju se samo delimično.
param-phase = Njegova faza
    .help = Koliko ovaj izvor prednjači u odnosu na zadatu fazu (ceo ciklus je 360°; negativno: kasni). Dva izvora pomerena za 180° šalju breg naspram dola: srednja linija između njih miruje.

## Postavke (naziv i ono što učenik čita)

preset-classic = Klasičan izgled
    .help = Jedna kugla koja ostaje gde je postavljena (taster G je pušta), zidovi koji odbijaju talase, kaustike: bazen kakav prikazuje klasični WebGL Water.
preset-calm = Mirna voda
    .help = Ništa u bazenu, male kapi, talasi koji brzo zamiru na upijajućim zidovima: mirna površina na kojoj se proučava jedan po jedan talasić.
preset-busy = Živahan bazen
    .help = Kugla i patka plutaju na brzoj, živahnoj vodi, s velikim kapima i zidovima koji odbijaju talase.
preset-fresnel = Lekcija: Fresnel-ova refleksivnost
    .help = Mirna, prazna voda posmatrana nisko preko bazena, pa upadni ugao raste od oko 50° blizu vas do klizećeg na daljoj strani: menjajte Fresnel-ov model i posmatrajte kako se menjaju odraz i grafik.
preset-glint = Lekcija: sunčev odsjaj
    .help = Pogled ka niskom suncu: prevucite preko vode da napravite talase i vidite Blinn-Phong odsjaj izdužen duž pogleda; prebacite Sunčev odsjaj na phong i menjajte sjajnost da uporedite.
preset-breeze = Lekcija: pozadinski talasi
    .help = Laki povetarac tera talase oštrih bregova preko bazena, ispod vaših talasića; prebacite Pozadinske talase na „modovi“ da vidite sopstvene stojeće talase bazena, koji svaki zid susreću vodoravno, na „gerstner“ za vodu koja se kreće u krugovima ili na „fft“ za spektar od hiljade talasa (dijagnostika „spektar“ pokazuje talase svakog modela).
preset-ocean = Lekcija: FFT okean
    .help = Tessendorf-ov okean u bazenu: Phillips spektar od oko hiljadu talasa na rešetki od 128 tačaka, sabran pomoću FFT u svakom kadru; dijagnostika pokazuje spektar, pomeren niz vetar.
preset-flat = Lekcija: ravna voda i praćenje zraka
    .help = Ravna voda iz igara (levo) naspram praćenja zraka (desno), kugla do pola izvan vode: prevucite razdelnik preko kugle. Levo, njena potopljena polovina stoji neiskrivljena na pravoj dubini, a odrazi se njišu za stalan pomak; desno, voda je prividno podiže i sve krivi prema nagibima talasa. Napravite talasiće i prebacite izobličenje na „talasići“ da vidite iste talase s lažnom optikom.
preset-lake = Lekcija: boja vode
    .help = Zelena jezerska voda: apsorbuje crvenu, zelenu i plavu svetlost brže od vode u bazenu i sama rasejava zelenoplavu svetlost, pa dublji kraj postaje zelen umesto taman (stavite rasejanu svetlost na 0 da vidite čisto Beer-Lambert-ovo slabljenje).
preset-noon = Podne
    .help = Sunce skoro u zenitu: tamnoplavo nebo, kratke senke, najsjajnije kaustike na dnu.
preset-evening = Veče
    .help = Nisko toplo sunce sa strane, slika eksponirana za njega: duge senke preko terase, voda tamna gde je obod zasenjuje, dalji zid osvetljen sunčevim kaustikama.
preset-sea = Lekcija: otvoreno more
    .help = Otvorena voda do horizonta na umerenom povetarcu: pet FFT kaskada s poljima različitih veličina, pa se nijedna šara ne ponavlja; mreža na kojoj se more crta projektuje se sa ekrana, pa detalji prate vaš pogled; izmaglica na horizontu izjednačava boju mora i neba (isključite Maglu da vidite ivicu mora); ostrvo ispred stoji u tirkiznom plićaku, s penom duž obale, i ogleda se u vodi (uključite „Prikaži mrežu“ da vidite mrežu). Kliknite blizu sredine da napravite talasiće u polju simulirane vode i gledajte kako se šire; gumena patka tamo, onoliko veća koliko je polje veće od bazena, ljulja se na talasima i ostavlja brazdu: prevucite je da je vidite.
preset-shore = Lekcija: talasići u plićaku
    .help = Plaža ostrva pored polja simulirane vode, na lakom povetarcu pod visokim suncem: nagibi talasa fokusiraju sunčevu svetlost u mrežu kaustika na pesku nekoliko metara ispod. Kliknite na vodu da napravite talasiće: gde je dubina odgovarajuća, njihovi prstenovi se fokusiraju u svetle linije na dnu, koje ih pokazuju mnogo bolje nego sama površina. Patka koja se ljulja pravi sopstvene prstenove, a njena senka pada na pesak.
preset-dawn = Mirno more u zoru
    .help = Nisko sunce ispred, nad mirnim morem: njegov odsjaj razvučen u dugu svetlucavu stazu na malim talasima, nebo toplo duž horizonta.
preset-storm = Oluja na moru
    .help = Jak vetar podiže talase od 5 m s izoštrenim bregovima pod niskim suncem, u gustoj izmaglici; patku bacakaju talasi među belim krestama.
preset-tank = Talasna kada: jedan izvor
    .help = Školska talasna kada odozgo: izvor se podiže i spušta deset puta u sekundi u sredini posude s vodom dubokom 10 mm, a lampa iznad kade baca njegove prstenove na ekran ispod kao svetle krugove, jer svaki breg fokusira svetlost kao sočivo. Prebacite prikaz na „visine“ da vidite same talase; menjajte frekvenciju i gledajte kako se prstenovi zbijaju (talasna dužina je brzina podeljena frekvencijom).
preset-single_slit = Talasna kada: jedan prorez
    .help = Prava šipka pravi ravne talase koji nailaze na pregradu s jednim otvorom. Iza otvora šire se u lepezu; što je otvor uži u odnosu na talasnu dužinu, to je lepeza šira (isprobajte širinu proreza).
preset-double_slit = Talasna kada: dva proreza
    .help = Ravni talasi prolaze kroz dva otvora na razmaku od 90 mm: talasi iz dva otvora se ukrštaju, i gde se breg susretne s bregom, ekran pokazuje svetle linije, a između njih, gde se breg susretne s dolom, voda miruje. Mirne linije se lepezasto šire pod uglovima pod kojima se putevi razlikuju za pola talasne dužine; prebacite prikaz na „intenzitet“ da ih vidite.
preset-refraction = Talasna kada: prelamanje
    .help = Ravni talasi nailaze na staklenu ploču pod vodom. Voda iznad nje je plića, pa se talasi usporavaju i zbijaju, a gde prelaze kosu ivicu ploče, skreću: Snell-ov zakon za talase na vodi.
preset-lens = Talasna kada: sočivo
    .help = Staklena ploča u obliku sočiva pod vodom: talasi se iznad nje usporavaju, a sredina svakog fronta najduže prolazi iznad ploče, pa pravi frontovi izlaze zakrivljeni i sastaju se u žiži iza nje, kao svetlost iza staklenog sočiva.
preset-doppler = Talasna kada: pokretni izvor
    .help = Izvor se kreće kroz kadu brzinom 0,12 m/s, oko 40 % brzine talasa: ispred njega se bregovi zbijaju, iza njega se razmiču, kao što visina tona sirene u prolazu raste i opada. Povećajte mu brzinu iznad brzine talasa (oko 0,31 m/s) i on pretiče sopstvene talase: pramčani talas.
preset-reflection = Talasna kada: zakrivljeno ogledalo
    .help = Pravi talasi nailaze na zakrivljeni zid u obliku parabole. Svaki deo zida vraća ih pod svojim uglom, i svi se sastaju u jednoj tački ispred njega, žiži, kao svetlost u ogledalu baterijske lampe ili u satelitskoj anteni. Prebacite prikaz na „intenzitet“ da vidite svetlu žižu.
preset-standing = Talasna kada: stojeći talasi
    .help = Pravi talasi nailaze na prav zid i vraćaju se kroz same sebe. Gde se susreću, sabiraju se u stojeće talase: linije mirne vode (čvorovi) na razmaku od pola talasne dužine, a između njih voda koja se podiže i spušta a ne odlazi nikuda. Prebacite prikaz na „visine“ i podesite stroboskop na frekvenciju izvora.
preset-phased_array = Talasna kada: fazirani niz
    .help = Četiri izvora u nizu, na razmaku od 30 mm (nešto više od pola talasne dužine na 6 Hz), svaki četvrtinu ciklusa iza prethodnog. Njihovi talasi se sabiraju samo u jednom pravcu, u snop okrenut za oko 25° ka kraju koji kasni: promenite fazni korak i snop se okreće, a da se ništa ne pomera, kao što radar sa faziranim nizom ili ultrazvučna sonda usmerava snop. Prebacite prikaz na „intenzitet“ da vidite snop.
