//! Golden images: every preset at 160x90 on lavapipe (validation required),
//! compared with the committed reference under a perceptual metric (MSSIM on
//! luma, RMS on chroma: image-compare's hybrid score, 1 = identical). On a
//! failure the test writes `NAME.actual.png` and `NAME.difference.png` next to
//! the golden. `BLACKHOLE_BLESS=1` writes new goldens instead: look at every
//! one before committing it.

mod common;

use std::path::PathBuf;

use common::{SceneSrc, render_png, scratch};

const W: u32 = 160;
const H: u32 = 90;
/// Lowest hybrid similarity accepted.
const MIN_SCORE: f64 = 0.97;

fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("golden")
}

#[test]
fn presets_match_their_golden_images() {
    let dir = scratch();
    let bless = std::env::var("BLACKHOLE_BLESS").is_ok_and(|v| v == "1");
    let mut failures = Vec::new();
    for (name, _, _) in blackhole::scene::PRESETS {
        let actual = render_png(&dir, name, SceneSrc::Preset(name), W, H);
        let golden_path = golden_dir().join(format!("{name}.png"));
        if bless {
            std::fs::create_dir_all(golden_dir()).unwrap();
            actual.save(&golden_path).unwrap();
            println!("blessed {}", golden_path.display());
            continue;
        }
        let golden = image::open(&golden_path)
            .unwrap_or_else(|e| {
                panic!(
                    "{}: {e}; run with BLACKHOLE_BLESS=1 to create it, then look at it",
                    golden_path.display()
                )
            })
            .to_rgb8();
        assert_eq!(golden.dimensions(), actual.dimensions(), "{name}: size");
        let sim =
            image_compare::rgb_hybrid_compare(&golden, &actual).expect("same-size images compare");
        println!("{name:12} similarity {:.5}", sim.score);
        if sim.score < MIN_SCORE {
            let actual_path = golden_dir().join(format!("{name}.actual.png"));
            let diff_path = golden_dir().join(format!("{name}.difference.png"));
            actual.save(&actual_path).unwrap();
            sim.image.to_color_map().save(&diff_path).unwrap();
            failures.push(format!(
                "{name}: similarity {:.4} < {MIN_SCORE} (wrote {} and {})",
                sim.score,
                actual_path.display(),
                diff_path.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The metric must see a real change: a shifted camera fails against the golden.
#[test]
fn the_metric_rejects_a_different_image() {
    let dir = scratch();
    let actual = render_png(
        &dir,
        "moved",
        SceneSrc::Toml("[camera]\nposition = [0.0, 3.0, -15.0]\n"),
        W,
        H,
    );
    let Ok(golden) = image::open(golden_dir().join("default.png")) else {
        panic!("tests/golden/default.png missing; bless the goldens first");
    };
    let sim = image_compare::rgb_hybrid_compare(&golden.to_rgb8(), &actual).unwrap();
    assert!(
        sim.score < MIN_SCORE,
        "a moved camera scored {:.4}",
        sim.score
    );
}
