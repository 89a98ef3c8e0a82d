//! `blackhole.Scene`: a scene from a preset, TOML text or a file, read and
//! changed key by key through the crate's own parsing and validation.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::{to_py, values};

/// A scene: the holes, the disk, the sky, the camera and every other key of
/// a scene file (docs/scenes.md). Keys are read and set by their dotted
/// path, `scene["camera.vfov_deg"] = 30` or `scene.set(...)`, validated as
/// a file is: a bad key or value raises ValueError with the command line's
/// message. Scenes are values: `copy()` or `with_key()` give new ones.
#[pyclass(module = "blackhole")]
#[derive(Clone)]
pub struct Scene {
    pub inner: blackhole::Scene,
}

#[pymethods]
impl Scene {
    /// The built-in default scene (what `blackhole render` draws).
    #[new]
    fn new() -> PyResult<Self> {
        blackhole::Scene::builtin_default()
            .map(|inner| Scene { inner })
            .map_err(to_py)
    }

    /// A built-in preset by name (`Scene.presets()` lists them).
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        if !blackhole::scene::preset_names().contains(&name) {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "no preset `{name}`; the presets are {}",
                blackhole::scene::preset_names().join(", ")
            )));
        }
        blackhole::Scene::load(name)
            .map(|inner| Scene { inner })
            .map_err(to_py)
    }

    /// The built-in presets' names.
    #[staticmethod]
    fn presets() -> Vec<&'static str> {
        blackhole::scene::preset_names()
    }

    /// A scene from TOML text (`origin` names it in messages).
    #[staticmethod]
    #[pyo3(signature = (text, origin = "<string>"))]
    fn from_toml(text: &str, origin: &str) -> PyResult<Self> {
        blackhole::Scene::from_toml(text, origin)
            .map(|inner| Scene { inner })
            .map_err(to_py)
    }

    /// A scene file (or a preset's name, as the command line takes it).
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Self> {
        let path = path.to_string_lossy().into_owned();
        blackhole::Scene::load(&path)
            .map(|inner| Scene { inner })
            .map_err(to_py)
    }

    /// The scene as TOML text (every key), which `from_toml` reads back to
    /// the same scene.
    fn to_toml(&self) -> PyResult<String> {
        self.inner.to_toml().map_err(to_py)
    }

    /// Writes the scene as a TOML file.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        let text = self.to_toml()?;
        std::fs::write(&path, text).map_err(|source| to_py(blackhole::Error::Io { path, source }))
    }

    /// The value of the key at the dotted path (`"camera.position"`,
    /// `"black_hole.0.spin"`; a table's path gives a dict).
    fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        let v = self.inner.key(key).map_err(to_py)?;
        values::to_object(py, &v)
    }

    /// Sets the key at the dotted path, validated as a file is (on
    /// ValueError the scene is left as it was).
    fn set(&mut self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let v = values::from_object(key, value)?;
        self.inner = self.inner.with_key(key, v).map_err(to_py)?;
        Ok(())
    }

    /// A copy with the key set (this scene unchanged).
    fn with_key(&self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<Self> {
        let mut s = self.clone();
        s.set(key, value)?;
        Ok(s)
    }

    /// A copy of the scene.
    fn copy(&self) -> Self {
        self.clone()
    }

    /// Every key as nested dicts (the TOML's tables).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let t = self.inner.to_table().map_err(to_py)?;
        values::to_object(py, &toml::Value::Table(t))
    }

    /// The scene at `time` seconds into its animation (the camera on its
    /// path, the disk turned), as a new scene.
    fn at_time(&self, time: f64) -> PyResult<Self> {
        if !time.is_finite() {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "time = {time}: must be a finite number of seconds"
            )));
        }
        Ok(Scene {
            inner: self.inner.at_time(time),
        })
    }

    /// The animation's frames per second (`[animation] fps`): frame i is
    /// at i / fps seconds.
    #[getter]
    fn fps(&self) -> f64 {
        self.inner.animation.fps
    }

    fn __getitem__<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        self.get(py, key)
    }

    fn __setitem__(&mut self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        self.set(key, value)
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.inner == other.inner
    }

    fn __repr__(&self) -> String {
        let s = &self.inner;
        let holes = s.black_holes.len();
        let spin = s.black_holes.first().map_or(0.0, |h| h.spin);
        format!(
            "Scene({holes} hole{}, spin {spin}, camera at {:?}, {:?} disk)",
            if holes == 1 { "" } else { "s" },
            s.camera.position,
            s.disk.kind
        )
    }

    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyDict>) -> Self {
        self.clone()
    }
}
