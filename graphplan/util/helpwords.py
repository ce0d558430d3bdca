"""The command line's help in the catalogue: every ``--help`` text (descriptions, option helps, the
words argparse itself prints and the metavars that are words) in Ukrainian and English, in the lab's
terms (docs/language.md). ``graphplan.cli.helps.speak`` puts them on the parser in one language.

A key is "COMMAND" (the one line of the commands' list), "COMMAND desc" (its description),
"COMMAND dest" (an option's help) or "* dest" (an option the commands share, unless the command has
its own); "@ word" is argparse's own word. Program names stay as the program writes them: options,
the values they take (uk, en, A1, kinematics …), formats (SVG, PDF, TOML, JSON, CSV), files and scene
tables ([cam]) — the help names them as one types them.
"""
from __future__ import annotations

HELPS: dict[str, tuple[str, str]] = {
    # argparse's own words
    "@ usage": ("використання: ", "usage: "),
    "@ positional": ("позиційні аргументи", "positional arguments"),
    "@ options": ("параметри", "options"),
    "@ commands": ("команди", "commands"),
    "@ help": ("показати цю довідку та вийти", "show this help message and exit"),
    "@ version": ("показати версію програми та вийти", "show program's version number and exit"),

    "graphplan desc": (
        "Графічні методи теорії механізмів і машин: плани положень, швидкостей і прискорень, "
        "кінематичні діаграми методом хорд і плани сил, виміряні так, як вимірює студент, і порівняні "
        "з точним аналітичним розв'язком. Мова довідки: --lang, інакше мова сцени, інакше українська.",
        "Graphical methods of the theory of machines and mechanisms: plans of positions, velocities "
        "and accelerations, kinematic diagrams by chords and force plans, measured like a student and "
        "compared with the exact analytic solution. The help's language: --lang, else the scene's, "
        "else Ukrainian."),
    "graphplan lang_before": (
        "мова всіх повідомлень і довідки: uk або en (те саме, що --lang після команди)",
        "language of every message and of the help: uk or en (the same as --lang after the command)"),

    # the commands' list
    "analyze": ("точна (аналітична) кінематика: положення, швидкості, прискорення",
                "exact (analytic) kinematics: positions, velocities, accelerations"),
    "sheet": ("аркуш креслення (SVG, PDF, PNG або DXF за розширенням)",
              "the drawing sheet (SVG, PDF, PNG or DXF by the suffix)"),
    "plans": ("графічні плани (положень, швидкостей, прискорень), виміряні й порівняні",
              "the graphical plans (positions, velocities, accelerations), measured and compared"),
    "diagrams": ("діаграми s–v–a методом хорд, виміряні й порівняні",
                 "s–v–a diagrams by the method of chords, measured and compared"),
    "forces": ("кінетостатика: плани сил, зрівноважувальний момент, важіль Жуковського",
               "kinetostatics: force plans, balancing moment, Zhukovsky lever"),
    "dynamics": ("зведені момент інерції й моменти, рівняння руху з двигуном, маховик",
                 "reduced inertia and moments, equation of motion with the motor, flywheel"),
    "key": ("ключі відповідей викладача для варіантів групи (JSON, CSV, аркуші ключів А4, зведення)",
            "teachers' answer keys for a group's variants (JSON, CSV, A4 key sheets, a summary)"),
    "check": ("оцінити довгу таблицю студента (варіант, положення, величина, значення) за ключем",
              "grade a student's long table (variant, position, quantity, value) against a key"),
    "bench": ("дослідження швидкодії, точності й стійкості: ТЕКА/bench.json і графіки",
              "speed–accuracy–stability study: DIR/bench.json plus charts"),
    "view": ("інтерактивний переглядач без мережі (один файл HTML)",
             "the offline interactive explorer (one HTML file)"),
    "cam": ("синтез кулачкового механізму графічними методами, порівняний з точним розв'язком",
            "cam synthesis by graphical methods, compared with the exact solution"),
    "serve": ("вебсторінка лабораторної на цьому комп'ютері (типово лише локальна адреса)",
              "the lab's web page on this machine (loopback by default)"),
    "gears": ("синтез зубчастих передач: евольвентна пара й планетарна передача, графічно і точно",
              "gear synthesis: the involute pair and the planetary train, graphical vs closed forms"),

    # shared options
    "* scene": ("файл сцени (TOML, див. docs/scenes.md); без нього — вбудований кривошипно-повзунний "
                "механізм",
                "scene file (TOML, see docs/scenes.md); the built-in crank-slider when omitted"),
    "* positions": ("кількість положень (типово: як у сцені)", "number of positions (default: the scene's)"),
    "* json": ("JSON за контрактом замість таблиць", "the contract's JSON instead of tables"),
    "* lang": ("мова таблиць, підписів, повідомлень і довідки: uk або en (типово: lang сцени, інакше uk)",
               "language of tables, captions, messages and the help: uk or en (default: the scene's "
               "lang, else uk)"),
    "* precision": ("точність креслення кожного накресленого й виміряного відрізка, мм (0 — точно; "
                    "типово 0,5)",
                    "drafting precision of every drawn and measured length, mm (0 = exact; default 0.5)"),

    "analyze desc": ("Точна кінематика кожної точки, ланки й поступальної пари.",
                     "Exact kinematics of every point, link and sliding pair."),
    "analyze phi": ("кути кривошипа замість положень (градуси від +x, проти годинникової стрілки)",
                    "crank angles instead of positions (deg from +x, counter-clockwise)"),

    "sheet desc": ("Компонування аркуша креслення: рамка, основний напис, плани, діаграми й таблиці. "
                   "Без СЦЕНИ креслиться вбудований кривошипно-повзунний механізм.",
                   "Lay out the drawing sheet: frame, title block, plans, diagrams and tables. Without "
                   "SCENE the built-in crank-slider is drawn."),
    "sheet scene": ("файл сцени (TOML); без нього — вбудований кривошипно-повзунний механізм",
                    "scene file (TOML); the built-in crank-slider when omitted"),
    "sheet output": ("вихідний файл: .svg, .pdf, .png або .dxf", "output file: .svg, .pdf, .png or .dxf"),
    "sheet format": ("формат аркуша: A1 (типово), A2, A3; що не вміщується, іде на наступні аркуші "
                     "комплекту (ФАЙЛ-2, ФАЙЛ-3 …)",
                     "sheet format: A1 (default), A2, A3; what does not fit goes to further sheets of "
                     "the set (FILE-2, FILE-3 …)"),
    "sheet sheet": ("який аркуш: kinematics (типовий для важільного механізму), forces, dynamics, cam "
                    "(типовий для сцени з [cam], docs/cams.md) або gears (типовий для сцени з "
                    "[gears]/[planetary], docs/gears.md)",
                    "which sheet: kinematics (the default of a lever mechanism), forces, dynamics, cam "
                    "(the default of a [cam] scene, docs/cams.md), or gears (the default of a "
                    "[gears]/[planetary] scene, docs/gears.md)"),
    "sheet accel": ("плани прискорень: кути в градусах або #номер положення",
                    "acceleration plans: degrees or #index"),
    "sheet precision": ("точність креслення (0 — точно)", "drafting precision (0 = exact)"),
    "sheet text_as_paths": ("записати написи контурами (SVG/PDF/PNG)",
                            "write lettering as outlines (SVG/PDF/PNG)"),
    "sheet dpi": ("роздільність PNG, точок на дюйм (типово 300, для друку)",
                  "PNG resolution in dots per inch (default 300, to print)"),

    "plans desc": ("План положень, плани швидкостей кожного положення і плани прискорень, побудовані "
                   "графічно в міліметрах креслення, виміряні лінійкою заданої точності й порівняні з "
                   "точним розв'язком.",
                   "Position plan, velocity plans of every position and acceleration plans, constructed "
                   "graphically in drawing millimetres, read with a ruler of the given precision and "
                   "compared with the exact solution."),
    "plans accel": ("плани прискорень при цих кутах кривошипа (градуси) або номерах положень, як #3 "
                    "(типово: як у сцені, інакше положення 1)",
                    "acceleration plans at these crank angles (deg) or position indices like #3 "
                    "(default: the scene's, else position 1)"),
    "plans precision": ("точність креслення кожного відліку, мм (типово 0,5; 0 — точно)",
                        "drafting precision of every reading, mm (default 0.5; 0 = exact)"),
    "plans mu_l": ("задати масштаб довжин μl, м/мм", "fix the length scale μl, m/mm"),
    "plans mu_v": ("задати масштаб швидкостей μv, (м/с)/мм", "fix the velocity scale μv, (m/s)/mm"),
    "plans mu_a": ("задати масштаб прискорень μa, (м/с²)/мм", "fix the acceleration scale μa, (m/s²)/mm"),
    "plans format": ("креслити в масштабах аркуша кінематики цього формату: A1 (типово), A2, A3, A4; "
                     "none — власні масштаби планів",
                     "draw at the scales the kinematics sheet of this format uses: A1 (default), A2, A3, "
                     "A4; none = the plans' own scales"),
    "plans svg": ("записати кожен план як SVG у справжніх міліметрах до ТЕКИ",
                  "write each plan as an SVG in true millimetres into DIR"),

    "diagrams desc": ("Кінематичні діаграми вихідної ланки (переміщення від положення 0, швидкість, "
                      "прискорення) графічним диференціюванням методом хорд з полюсними відстанями H1, "
                      "H2; зворотне графічне інтегрування; кожна ордината виміряна з точністю креслення "
                      "й порівняна з аналітичним розв'язком.",
                      "Kinematic diagrams of the output (displacement from position 0, velocity, "
                      "acceleration) by graphical differentiation with chords and pole distances H1, "
                      "H2; graphical integration back; every ordinate read with the drafting precision "
                      "and compared with the analytic solver."),
    "diagrams point": ("точка повзуна або ланка (типово: вихідна ланка сцени)",
                       "a sliding point or a link (default: the scene's output)"),
    "diagrams divisions": ("рівні інтервали (типово: кількість положень сцени) або через кому кути "
                           "повороту кривошипа від положення 0 у градусах для нерівних",
                           "equal intervals (default: the scene's positions count), or comma-separated "
                           "crank turns from position 0 in degrees for unequal ones"),
    "diagrams h1": ("полюсна відстань діаграми v (як у сцені, інакше 30)",
                    "pole distance of the v diagram (the scene's, else 30)"),
    "diagrams h2": ("полюсна відстань діаграми a (як у сцені, інакше 30)",
                    "pole distance of the a diagram (the scene's, else 30)"),
    "diagrams L": ("відрізок осі абсцис на один оберт кривошипа (як у сцені, інакше 240)",
                   "abscissa of one crank period (the scene's, else 240)"),
    "diagrams precision": ("точність креслення кожного відліку (0,5; 0 — точно)",
                           "drafting precision of every reading (0.5; 0 = exact)"),
    "diagrams adaptive": ("ділити інтервали там, де оцінка похибки хорд велика (екстремуми, різкі "
                          "згини)",
                          "split intervals where the chord error estimate is large (extrema, sharp bends)"),
    "diagrams tolerance": ("межа оцінки похибки хорд на діаграмах v і a в адаптивному режимі (0,5)",
                           "the adaptive mode's chord error estimate limit on the v and a diagrams (0.5)"),
    "diagrams method": ("графічне диференціювання: chords — хорди (як у сцені, інакше хорди) або "
                        "tangents — дотичні за дзеркалом",
                        "graphical differentiation: chords (the scene's, else chords) or tangents by "
                        "the mirror"),
    "diagrams angle_error": ("дотичні: напрям кожної дотичної відхилено до ± стількох градусів (типово: "
                             "межа дзеркала, docs/diagrams.md; 0 — точні дотичні; детерміновано)",
                             "tangents: each tangent's direction off by up to ± this many degrees "
                             "(default: the mirror's bound, docs/diagrams.md; 0 = exact tangents; "
                             "deterministic)"),
    "diagrams correct": ("хорди: поправка площ кривих v і a, як у лабораторній (без неї — простий метод)",
                         "chords: the lab's area correction of the v and a curves (off: the plain method)"),
    "diagrams height": ("вписати діаграму s у цю висоту (μs за рядом значень)",
                        "fit the s diagram to this height (μs from the series)"),
    "diagrams at": ("положення таблиці лабораторної (типово 1 і N/2+1)",
                    "positions of the lab's table (default 1 and N/2+1)"),
    "diagrams format": ("L, висота s і H1, H2 як на аркуші кінематики цього формату: A1 (типово), A2, "
                        "A3, A4; none — таблиця [diagrams] сцени",
                        "L, the s height and H1, H2 as the kinematics sheet of this format draws them: "
                        "A1 (default), A2, A3, A4; none = the scene's [diagrams] table"),
    "diagrams svg": ("записати три діаграми з їхніми побудовами полюсів",
                     "write the three diagrams with their pole constructions"),

    "forces desc": ("Силовий аналіз при одному куті кривошипа, група за групою від останньої групи "
                    "Ассура до кривошипа: реакції з планів сил (виміряні з точністю креслення) проти "
                    "точної формули і зрівноважувальний момент на кривошипі за точною формулою, "
                    "планами сил, важелем Жуковського і балансом потужностей.",
                    "Force analysis at one crank angle, group by group from the last Assur group to "
                    "the crank: the reactions read off force plans (measured to the drafting precision) "
                    "against the closed form, and the balancing moment on the crank by the closed form, "
                    "the force plans, the Zhukovsky lever and power balance."),
    "forces scene": ("файл сцени (TOML, див. docs/scenes.md)", "scene file (TOML, see docs/scenes.md)"),
    "forces phi": ("кут кривошипа (градуси від +x, проти годинникової стрілки); типово: "
                   "positions.force_phi_deg сцени від положення 0, інакше положення 1",
                   "crank angle (deg from +x, counter-clockwise); default: the scene's "
                   "positions.force_phi_deg from position 0, else position 1"),
    "forces format": ("μl і μF як на силовому аркуші цього формату (у силовому положенні сцени): A1 "
                      "(типово), A2, A3, A4; none — власні масштаби планів сил",
                      "μl and μF as the force sheet of this format draws them (at the scene's force "
                      "position): A1 (default), A2, A3, A4; none = the force plans' own scales"),
    "forces svg": ("записати ТЕКА/forces.svg (групи, плани сил, важіль)",
                   "write DIR/forces.svg (groups, force plans, lever)"),
    "forces charts": ("записати до ТЕКИ зрівноважувальний момент за оберт і годографи реакцій "
                      "(balancing_moment.png/.svg, hodographs.png/.svg)",
                      "write the balancing moment over a turn and the reactions' hodographs to DIR "
                      "(balancing_moment.png/.svg, hodographs.png/.svg)"),

    "dynamics desc": ("Динаміка машини, зведена до кривошипа (методичка 003): I*(φ), M*(φ), усталений "
                      "рух за рівнянням руху зі сталим рушійним моментом і з двигуном, маховик для "
                      "коефіцієнта нерівномірності δ графічною побудовою енергія–маса (Віттенбауера), "
                      "виміряною з точністю креслення, проти точного.",
                      "Dynamics of the machine reduced to the crank (seed 003): I*(φ), M*(φ), the steady "
                      "state of the equation of motion with a constant driving moment and with the motor, "
                      "and the flywheel for a coefficient of unevenness δ by the graphical energy–mass "
                      "(Wittenbauer) construction, measured to the drafting precision, against the exact "
                      "one."),
    "dynamics scene": ("файл сцени (TOML, див. docs/scenes.md і docs/dynamics.md)",
                       "scene file (TOML, see docs/scenes.md and docs/dynamics.md)"),
    "dynamics delta": ("коефіцієнт нерівномірності δ у (0; 0,5); типово: delta з [dynamics] сцени, "
                       "інакше 0,04",
                       "coefficient of unevenness δ in (0, 0.5); default: the scene's [dynamics] delta, "
                       "else 0.04"),
    "dynamics divisions": ("поділок оберту на діаграмах, від 4 до 360 (типово: divisions з [dynamics] "
                           "сцени, інакше кількість її положень, не більше 360)",
                           "divisions of the turn on the diagrams, 4 to 360 (default: the scene's "
                           "[dynamics] divisions, else its number of positions, at most 360)"),
    "dynamics format": ("вивести побудову (L, масштаби, H), яку креслить аркуш динаміки цього формату: "
                        "A1 (типово), A2, A3",
                        "report the construction (L, scales, H) the dynamics sheet of this format draws: "
                        "A1 (default), A2, A3"),
    "dynamics svg": ("записати діаграми до ТЕКИ (moments, energy, inertia, wittenbauer, speed .svg)",
                     "write the diagrams to DIR (moments, energy, inertia, wittenbauer, speed .svg)"),

    "key desc": ("Точні відповіді для кожного варіанта таблиці над базовою сценою (docs/keys.md): "
                 "швидкості в кожному положенні, прискорення в положеннях планів прискорень, s, v, a "
                 "вихідної ланки в поділках діаграми, з допусками.",
                 "Exact answers for every variant of a table over a base scene (docs/keys.md): "
                 "velocities at every position, accelerations at the acceleration-plan positions, the "
                 "output's s, v, a at the diagram's divisions, with tolerances."),
    "key variants": ("таблиця варіантів: CSV (або .toml), рядок на варіант",
                     "the variant table: CSV (or .toml), one row per variant"),
    "key output": ("тека для ключів", "folder for the keys"),
    "key tolerance": ("допуск, %%, кожної величини без власного (типово: як у таблиці, інакше 5)",
                      "the tolerance, %%, of every quantity without a setting of its own (default: the "
                      "table's, else 5)"),
    "key tol": ("допуск величини, %%; шаблони як в оболонці: --tol 'a_*=8' (можна повторювати)",
                "a quantity's tolerance, %%; shell-style patterns: --tol 'a_*=8' (repeatable)"),
    "key divisions": ("поділки діаграми (типово: як у таблиці, інакше кількість положень сцени)",
                      "the diagram's divisions (default: the table's, else the scene's positions)"),
    "key no_pdf": ("записати лише аркуші ключів SVG", "write the SVG key sheets only"),
    "key jobs": ("будувати варіанти в N процесах одночасно (типово: кількість процесорів, не більше 8)",
                 "variants built in N processes at once (default: the processors, at most 8)"),
    "key quiet": ("без індикатора поступу", "no progress bar"),
    "key json": ("вивести зведення як JSON", "print the summary as JSON"),

    "check desc": ("Для кожного рядка — точне значення, похибка у відсотках і зараховано/не "
                   "зараховано за допуском ключа; для незарахованого рядка шукається положення за "
                   "оберт, якому він відповідає, і воно називається. Потім зведення.",
                   "Per row the exact value, the percent error and pass/fail by the key's tolerance; a "
                   "failing row is searched over the turn and, when it fits another position, that "
                   "position is named. Then a summary."),
    "check key": ("тека ключів, записана 'graphplan key', тека варіанта або її key.json",
                  "a key folder written by 'graphplan key', a variant's folder or its key.json"),
    "check student": ("таблиця студента: CSV з position, quantity, value (і variant)",
                      "the student's table: CSV with position, quantity, value (and variant)"),
    "check json": ("оцінені рядки й зведення як JSON", "the graded rows and the summary as JSON"),
    "check signed": ("порівнювати знаки величин зі знаком (ω, ε, s, v, a), а не модулі",
                     "compare signs of signed quantities (ω, ε, s, v, a) instead of magnitudes"),

    "bench desc": ("Час і похибки аналітичного розв'язувача, графічних планів і діаграм методом хорд; "
                   "розгортки аж до відмов механізмів.",
                   "Times and errors of the analytic solver, the graphical plans and the chord "
                   "diagrams; sweeps toward the mechanisms' failures."),
    "bench out": ("тека результатів (типово: bench)", "output folder (default: bench)"),
    "bench quick": ("короткий прогін (менше хвилини)", "a short run (under a minute)"),
    "bench section": ("виконати лише цей розділ (можна повторювати): speed, chords, differentiation, "
                      "plans, stability, sheet, external, flywheel, cam, gears або processes (цілі "
                      "команди проти самого імпорту numpy, shapely і svgwrite; лише на вимогу)",
                      "run only this section (repeatable): speed, chords, differentiation, plans, "
                      "stability, sheet, external, flywheel, cam, gears, or processes (whole commands "
                      "against the bare import of numpy, shapely and svgwrite; only when asked for)"),

    "view desc": ("Одна самодостатня сторінка HTML: механізм, що рухається повзунком кута кривошипа, "
                  "плани швидкостей і прискорень поточного кута з таблицею значень (графічні в "
                  "положеннях лабораторної, точні, похибка у відсотках), кожна побудова крок за "
                  "кроком, діаграми s–v–a і попередження. Відкривається в будь-якому браузері; "
                  "мережею не користується.",
                  "One self-contained HTML page: the mechanism moving with a crank-angle slider, the "
                  "velocity and acceleration plans of the current angle with the table of values "
                  "(graphical at the lab's positions, exact, percent error), each construction "
                  "replayed step by step, the s–v–a diagrams and the warnings. Open it in any browser; "
                  "it makes no network request."),
    "view output": ("сторінка, яку записати", "the page to write"),
    "view precision": ("точність креслення відліків планів, мм (типово 0,5; 0 — точно)",
                       "drafting precision of the plans' readings, mm (default 0.5; 0 = exact)"),
    "view format": ("плани в масштабах аркуша кінематики цього формату: A1 (типово), A2, A3, A4; none — "
                    "власні масштаби планів",
                    "the plans at the scales the kinematics sheet of this format uses: A1 (default), "
                    "A2, A3, A4; none = the plans' own scales"),
    "view step": ("крок кута кривошипа точного розв'язку, градуси (типово 1)",
                  "the crank-angle grid of the exact solution, degrees (default 1)"),

    "cam desc": ("Кулачковий механізм (сцена з [cam], docs/cams.md): закон руху штовхача, його аналог "
                 "прискорення, двічі зінтегрований методом хорд, найменший радіус основної шайби з "
                 "фазової діаграми й допустимих кутів тиску, профіль методом обернення руху — кожне "
                 "значення виміряне лінійкою поруч із точним і похибкою у відсотках.",
                 "A cam mechanism (a [cam] scene, docs/cams.md): the follower's law, its analogue "
                 "acceleration integrated twice by chords, the smallest base radius from the phase "
                 "diagram and the allowed pressure angles, the profile by inversion — every value "
                 "measured with the ruler beside the exact one with the percent error."),
    "cam scene": ("файл сцени кулачка (TOML з таблицею [cam]; examples/cam_translating.toml)",
                  "a cam scene file (TOML with a [cam] table; examples/cam_translating.toml)"),
    "cam divisions": ("інтервали фази підйому і фази опускання (типово: як у сцені, інакше 8)",
                      "intervals of the rise and of the return (default: the scene's, else 8)"),
    "cam svg": ("записати побудови до ТЕКИ (diagrams, phase, profile .svg)",
                "write the constructions to DIR (diagrams, phase, profile .svg)"),
    "cam format": ("аркуш, масштаби якого бере побудова (типово A1: числа — як на аркуші кулачка)",
                   "the sheet whose scales the construction takes (default A1: the numbers are the cam "
                   "sheet's)"),

    "serve desc": ("Вебсторінка для студентів (заповнити шаблон або завантажити TOML, переглянути "
                   "механізм, завантажити аркуші, переглядач і таблиці) і викладачів (варіанти → "
                   "ключі, таблиці студентів → оцінки). Типово лише локальна адреса; будь-який інший "
                   "--host просить у кожного відвідувача токен, надрукований під час запуску "
                   "(docs/serve.md).",
                   "A web page for students (a template filled in or a TOML uploaded, the mechanism "
                   "previewed, the sheets, the explorer and the tables downloaded) and teachers "
                   "(variants → keys, students' tables → grades). Loopback by default; any other "
                   "--host asks every visitor for the token printed at start (docs/serve.md)."),
    "serve host": ("адреса, яку слухати (типово 127.0.0.1)", "address to listen on (default 127.0.0.1)"),
    "serve port": ("порт (типово 8000)", "port (default 8000)"),
    "serve open": ("відкрити сторінку в браузері", "open the page in the browser"),
    "serve workers": ("робочих процесів, що рахують одночасно (типово 2)",
                      "worker processes computing at once (default 2)"),
    "serve timeout": ("межа часу одного аркуша, переглядача чи оцінювання, секунди (типово 120)",
                      "time bound of one sheet, explorer or grading, seconds (default 120)"),
    "serve lang": ("перша мова сторінки, мова повідомлень і довідки цієї команди: uk або en (типово: "
                   "мова браузера, інакше uk; повідомлення uk)",
                   "the page's first language and of this command's messages and help: uk or en "
                   "(default: the browser's, else uk; messages uk)"),

    "gears desc": ("Сцена зубчастих передач ([gears] і/або [planetary], docs/gears.md): геометрія й "
                   "якісні показники евольвентної пари зі зміщенням (зміщення задані або \"auto\"), "
                   "накресленої в зачепленні з εα, виміряним на кресленні; планетарна передача за "
                   "формулою Вілліса (числа зубців задані або дібрані під передаточне відношення), за "
                   "картиною швидкостей і планом кутових швидкостей — кожен відлік поруч із точним "
                   "значенням і похибкою у відсотках.",
                   "A gear scene ([gears] and/or [planetary], docs/gears.md): the shifted involute "
                   "pair's geometry and quality (shifts given or \"auto\"), drawn in mesh with εα "
                   "measured off the drawing; the planetary train by Willis' formula (z's given or "
                   "chosen for the ratio) and by its velocity picture and plan of angular velocities — "
                   "every reading beside the exact value with the percent error."),
    "gears scene": ("файл сцени зубчастих передач (TOML з [gears] і/або [planetary]; examples/gears.toml)",
                    "a gear scene file (TOML with [gears] and/or [planetary]; examples/gears.toml)"),
    "gears svg": ("записати побудови до ТЕКИ (meshing, sliding, planetary .svg)",
                  "write the constructions to DIR (meshing, sliding, planetary .svg)"),
    "gears format": ("аркуш, масштаби якого бере побудова (типово A1: числа — як на аркуші передач; "
                     "A2/A3 — як у комплекті)",
                     "the sheet whose scales the construction takes (default A1: the numbers are the gear "
                     "sheet's; A2/A3: the set's)"),
}

# metavars that are words (a letter, a format or a symbol stays): English as the contract writes them
METAVARS: dict[str, tuple[str, str]] = {
    "COMMAND": ("КОМАНДА", "COMMAND"),
    "FORMAT": ("ФОРМАТ", "FORMAT"),
    "FILE": ("ФАЙЛ", "FILE"),
    "FILE.html": ("ФАЙЛ.html", "FILE.html"),
    "DIR": ("ТЕКА", "DIR"),
    "MM": ("ММ", "MM"),
    "DEG": ("ГРАД", "DEG"),
    "AT": ("КУТ", "AT"),
    "PCT": ("ВІДС", "PCT"),
    "QUANTITY=PCT": ("ВЕЛИЧИНА=ВІДС", "QUANTITY=PCT"),
    "NAME": ("РОЗДІЛ", "NAME"),
    "S": ("СЕК", "S"),
    "M_PER_MM": ("МАСШТАБ", "M_PER_MM"),
    "V_PER_MM": ("МАСШТАБ", "V_PER_MM"),
    "A_PER_MM": ("МАСШТАБ", "A_PER_MM"),
    "HOST": ("АДРЕСА", "HOST"),
    "PORT": ("ПОРТ", "PORT"),
    "WORKERS": ("ПРОЦЕСИ", "WORKERS"),
    # positionals: argparse shows their names
    "scene": ("СЦЕНА", "SCENE"),
    "variants": ("ВАРІАНТИ", "VARIANTS"),
    "key": ("КЛЮЧ", "KEY"),
    "student": ("СТУДЕНТ", "STUDENT"),
}


def help_text(key: str, lang: str) -> str:
    """The help's text for ``key`` in ``lang`` (KeyError when the catalogue lacks it)."""
    uk, en = HELPS[key]
    return uk if lang == "uk" else en
