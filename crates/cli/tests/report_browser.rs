//! report.html in a real browser: `stickslip run --out` on a few shipped scenes, then
//! headless Chromium loads each report (no console message, every plot in the DOM) and
//! takes screenshots: each plot must be non-blank where it is drawn. Skipped, saying why,
//! when no Chromium is installed (`.ci/run` installs the Debian package `chromium`).
//!
//! `STICKSLIP_UPDATE_SCREENSHOT=1` also writes docs/images/report.png (the top of the first
//! report).

use std::path::{Path, PathBuf};
use std::process::Command;

/// Scenes whose reports are checked: a 2D line contact with a subsurface field, a 3D grid
/// with stick/slip maps, and a load cycle.
const SCENES: [&str; 3] = ["hertz_cylinder_cattaneo", "seed002_ex4_square", "sphere_load_cycle"];

/// A cell of the plot grid (CSS pixels): every plot (at most 720 x 600) fits one.
const CELL: (u32, u32) = (740, 620);

fn chromium() -> Option<PathBuf> {
    let candidates = ["/usr/bin/chromium", "/usr/bin/chromium-browser"];
    candidates.iter().map(PathBuf::from).find(|p| p.exists())
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("stickslip-report-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Run headless Chromium on `url` with `args`; its stderr (logging on).
fn browse(chrome: &Path, profile: &Path, args: &[&str], url: &str) -> (String, String) {
    let o = Command::new(chrome)
        .args(["--headless", "--disable-gpu", "--no-sandbox", "--hide-scrollbars"])
        .args(["--enable-logging=stderr", "--v=0", "--no-first-run"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(url)
        .output()
        .expect("chromium starts");
    assert!(o.status.success(), "chromium failed on {url}: {}", String::from_utf8_lossy(&o.stderr));
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// RGB pixels of a PNG (8-bit RGB or RGBA) with its width and height.
fn decode(path: &Path) -> (Vec<[u8; 3]>, u32, u32) {
    let dec = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size().unwrap()];
    let info = r.next_frame(&mut buf).unwrap();
    let step = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        c => panic!("unexpected PNG colour type {c:?}"),
    };
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let px = buf[..info.buffer_size()].chunks(step).map(|c| [c[0], c[1], c[2]]).collect();
    (px, info.width, info.height)
}

/// Check one scene's report; returns its directory.
fn check(chrome: &Path, name: &str) -> PathBuf {
    let base = tmp(name);
    let out = base.join("out");
    let scene =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes").join(format!("{name}.toml"));
    let o = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{name}: {}", String::from_utf8_lossy(&o.stderr));
    let report = out.join("report.html");
    let html = std::fs::read_to_string(&report).unwrap();
    let svgs: Vec<String> = {
        let mut v: Vec<String> = std::fs::read_dir(&out)
            .unwrap()
            .filter_map(Result::ok)
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".svg"))
            .collect();
        v.sort();
        v
    };
    let plots = html.matches("<figure class=\"plot\"").count();
    assert!(plots >= 3, "{name}: {plots} plots in report.html");
    assert_eq!(plots, svgs.len(), "{name}: every SVG written is in the report");
    // Self-contained: nothing is fetched and nothing runs.
    // (An SVG's xmlns names its namespace; it is not fetched.)
    for bad in ["<script", "src=", "href=\"http", "url(", "@import", "<link rel=\"stylesheet\""] {
        assert!(!html.contains(bad), "{name}: report.html holds {bad}");
    }

    // 1. The report itself loads without a console message and its DOM holds every plot.
    let profile = base.join("profile");
    let url = format!("file://{}", report.display());
    let (dom, log) = browse(chrome, &profile, &["--dump-dom"], &url);
    let console: Vec<&str> = log.lines().filter(|l| l.contains(":CONSOLE")).collect();
    assert!(console.is_empty(), "{name}: console messages: {console:#?}");
    assert_eq!(dom.matches("<figure class=\"plot\"").count(), plots, "{name}: plots in the DOM");

    // 2. Screenshots: the top of the report (it must show text), and the report with a style
    //    added that hides everything but the plots and sets plot i in cell i of a grid.
    let top = base.join("top.png");
    browse(
        chrome,
        &profile,
        &["--window-size=1100,900", &format!("--screenshot={}", top.display())],
        &url,
    );
    let (px, _, _) = decode(&top);
    let ink = px.iter().filter(|p| p.iter().any(|&c| c < 200)).count();
    assert!(ink > 2000, "{name}: the top of the report is (nearly) blank: {ink} dark pixels");

    let cols = 2u32;
    let rows = (plots as u32).div_ceil(cols);
    let mut css = String::from(
        "<style>body{margin:0;padding:0;max-width:none}body>*{display:none}\
         body>figure.plot{display:block;position:absolute;margin:0;width:720px;overflow:hidden}\
         figcaption{display:none}",
    );
    for i in 0..plots as u32 {
        css.push_str(&format!(
            "#plot-{i}{{left:{}px;top:{}px}}",
            (i % cols) * CELL.0,
            (i / cols) * CELL.1
        ));
    }
    css.push_str("</style>");
    assert!(html.contains("</head>"));
    let grid_page = base.join("grid.html");
    std::fs::write(&grid_page, html.replacen("</head>", &format!("{css}</head>"), 1)).unwrap();
    let shot = base.join("grid.png");
    browse(
        chrome,
        &profile,
        &[
            &format!("--window-size={},{}", cols * CELL.0, rows * CELL.1),
            "--force-device-scale-factor=1",
            &format!("--screenshot={}", shot.display()),
        ],
        &format!("file://{}", grid_page.display()),
    );
    let (px, w, h) = decode(&shot);
    assert!(w >= cols * CELL.0 && h >= rows * CELL.1, "{name}: screenshot {w} x {h}");
    for i in 0..plots as u32 {
        let (x0, y0) = ((i % cols) * CELL.0, (i / cols) * CELL.1);
        let (mut ink, mut colour) = (0usize, 0usize);
        for y in y0..y0 + CELL.1 {
            for x in x0..x0 + CELL.0 {
                let [r, g, b] = px[(y * w + x) as usize];
                if r < 235 || g < 235 || b < 235 {
                    ink += 1;
                }
                if r.abs_diff(g) > 15 || g.abs_diff(b) > 15 || r.abs_diff(b) > 15 {
                    colour += 1;
                }
            }
        }
        let area = (CELL.0 * CELL.1) as usize;
        println!(
            "{name} plot {i}: {ink} drawn pixels ({:.1} %), {colour} in colour",
            100.0 * ink as f64 / area as f64
        );
        // Axes, ticks and labels alone make about 1 % of a cell; the data is in colour.
        assert!(
            ink * 100 > area,
            "{name}: plot {i} is (nearly) blank: {ink} of {area} pixels drawn"
        );
        assert!(colour > 500, "{name}: plot {i} shows no data in colour: {colour} pixels");
    }
    base
}

#[test]
fn reports_render_in_headless_chromium() {
    let Some(chrome) = chromium() else {
        println!(
            "skipped: no Chromium at /usr/bin/chromium (install the Debian package `chromium`; \
             .ci/run does so when it can)"
        );
        return;
    };
    let dirs: Vec<PathBuf> = std::thread::scope(|s| {
        let hs: Vec<_> = SCENES.iter().map(|n| s.spawn(|| check(&chrome, n))).collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    if std::env::var_os("STICKSLIP_UPDATE_SCREENSHOT").is_some() {
        let to = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/images/report.png");
        std::fs::copy(dirs[0].join("top.png"), to).unwrap();
    }
    for d in dirs {
        let _ = std::fs::remove_dir_all(d);
    }
}
