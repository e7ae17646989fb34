//! A scene file loaded once for a figure that renders it again and again (the later chapters'
//! error against time): the world with its motion, the file's path options, the size the
//! figure level asks for, and the materials tabulated once, since the renders are timed and
//! the tables are the same for every one.

use crate::SceneMaterials;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::PathOptions;
use ch08_path_tracing::lab::scene_file::path_options;
use std::path::Path;
use workbench::figure_set::Level;

/// A scene file ready to be rendered by a figure.
pub struct FigureScene {
    /// The scene, with its motion.
    pub world: MotionScene,
    /// Its materials, tabulated.
    pub materials: SceneMaterials,
    /// The file's path options (its integrator's depth, roulette, `hide_emitters`).
    pub options: PathOptions,
    /// The image size: half the film's at the quick level, the film's in the book.
    pub width: u32,
    /// See `width`.
    pub height: u32,
}

impl FigureScene {
    /// The scene file at `path`, at `level`'s size.
    pub fn load(path: &Path, level: Level) -> anyhow::Result<Self> {
        let loaded = workbench::scene_file::load_scene_file(path, &[])?;
        let options = path_options(&loaded.scene);
        let world = MotionScene::new(loaded.scene).map_err(anyhow::Error::msg)?;
        let film = world.scene.film;
        let (width, height) =
            level.pick((film.width / 2, film.height / 2), (film.width, film.height));
        let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
        Ok(Self {
            world,
            materials,
            options,
            width,
            height,
        })
    }
}
