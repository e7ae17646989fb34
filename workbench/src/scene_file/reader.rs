//! The state of reading one scene: the element tree, the `$name` parameters, the objects an
//! `id` names (so that `<ref>` may point forwards or backwards), and the warnings gathered so
//! far.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

use super::bitmap::DecodedImage;
use super::element::{Element, SceneTree, folders_for, resolve_file};
use super::error::{SceneError, SceneWarning, TextPosition};
use super::values::{parse_float, parse_vec3, substitute};
use common::scene::{Bitmap, Material, Texture};
use glam::Vec3;

/// Reads attributes with `$name` substitution, follows references and turns problems into
/// located errors. `'a` is the life of the element tree.
pub(super) struct Reader<'a> {
    /// The scene file, for messages.
    pub file: &'a Path,
    parameters: &'a HashMap<String, String>,
    search_folders: &'a [PathBuf],
    elements_by_id: HashMap<String, &'a Element>,
    /// BSDFs already read, by id, so that each is read once however often it is referenced.
    pub bsdfs_by_id: HashMap<String, Material>,
    /// Textures with an id, read once.
    pub textures_by_id: HashMap<String, Texture>,
    /// The images bitmap textures read, in the order they were first read.
    pub bitmaps: Vec<Bitmap>,
    /// Each image file's pixels, decoded once per file and `raw` setting.
    pub images_by_file: HashMap<(PathBuf, bool), DecodedImage>,
    /// Ids whose object is being read, to refuse an object that refers to itself.
    reading: HashSet<String>,
    /// Ids that were referenced, to warn about objects declared apart and never used.
    pub referenced: HashSet<String>,
    /// Ignored things worth telling the user about.
    pub warnings: Vec<SceneWarning>,
}

impl<'a> Reader<'a> {
    /// A reader of `tree`, the scene file `file` and what it includes.
    pub fn new(file: &'a Path, tree: &'a SceneTree) -> Result<Self, SceneError> {
        Ok(Reader {
            file,
            parameters: &tree.parameters,
            search_folders: &tree.search_folders,
            elements_by_id: tree.elements_by_id(file)?,
            bsdfs_by_id: HashMap::new(),
            textures_by_id: HashMap::new(),
            bitmaps: Vec::new(),
            images_by_file: HashMap::new(),
            reading: HashSet::new(),
            referenced: HashSet::new(),
            warnings: Vec::new(),
        })
    }

    /// Where `node` starts.
    pub fn position(&self, node: &Element) -> TextPosition {
        node.position.clone()
    }

    /// An error at `position`.
    pub fn error_at(&self, position: TextPosition, message: impl Into<String>) -> SceneError {
        SceneError::at(self.file, &position, message)
    }

    /// An error at the start of `node`.
    pub fn error(&self, node: &Element, message: impl Into<String>) -> SceneError {
        SceneError::at(self.file, &node.position, message)
    }

    /// Records a warning at `position`.
    pub fn warn_at(&mut self, position: TextPosition, message: impl Into<String>) {
        let SceneError {
            file,
            line,
            column,
            message,
        } = self.error_at(position, message);
        self.warnings.push(SceneWarning {
            file,
            line,
            column,
            message,
        });
    }

    /// The attribute `name` of `node` with `$name`s substituted, if present.
    pub fn attribute(&self, node: &Element, name: &str) -> Result<Option<String>, SceneError> {
        match node.attribute(name) {
            None => Ok(None),
            Some(raw) => substitute(raw, self.parameters)
                .map(Some)
                .map_err(|message| self.error(node, message)),
        }
    }

    /// The attribute `name` of `node`, which must be present.
    pub fn required_attribute(&self, node: &Element, name: &str) -> Result<String, SceneError> {
        self.attribute(node, name)?.ok_or_else(|| {
            let tag = node.name();
            self.error(node, format!("<{tag}> needs a \"{name}\" attribute"))
        })
    }

    /// Parses the attribute `name` of `node` with `parse`, locating any error at `node`.
    pub fn parsed_attribute<T>(
        &self,
        node: &Element,
        name: &str,
        parse: impl Fn(&str) -> Result<T, String>,
    ) -> Result<Option<T>, SceneError> {
        match self.attribute(node, name)? {
            None => Ok(None),
            Some(text) => parse(&text).map(Some).map_err(|message| {
                let tag = node.name();
                self.error(node, format!("attribute \"{name}\" of <{tag}>: {message}"))
            }),
        }
    }

    /// A point or vector written as `value="x, y, z"` or as `x`, `y`, `z` attributes of
    /// `node` (each 0 when left out).
    pub fn xyz(&self, node: &Element) -> Result<Vec3, SceneError> {
        if let Some(value) = self.parsed_attribute(node, "value", parse_vec3)? {
            return Ok(value);
        }
        let mut xyz = Vec3::ZERO;
        for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
            if let Some(coordinate) = self.parsed_attribute(node, name, parse_float)? {
                xyz[axis] = coordinate;
            }
        }
        Ok(xyz)
    }

    /// The object `node` stands for: the element a `<ref id="..."/>` names (declared before or
    /// after it, anywhere in the scene or the files it includes), or `node` itself.
    pub fn dereference(&mut self, node: &'a Element) -> Result<&'a Element, SceneError> {
        if !node.has_name("ref") {
            return Ok(node);
        }
        let id = self.required_attribute(node, "id")?;
        let target = self.elements_by_id.get(&id).copied().ok_or_else(|| {
            self.error(
                node,
                format!("<ref id=\"{id}\"> names nothing: no element of the scene has id=\"{id}\""),
            )
        })?;
        self.referenced.insert(id);
        Ok(target)
    }

    /// Marks `id` as being read; an error when it already is (the object refers to itself).
    pub fn start_reading(&mut self, node: &Element, id: &str) -> Result<(), SceneError> {
        if self.reading.insert(id.to_string()) {
            Ok(())
        } else {
            Err(self.error(
                node,
                format!("the object with id \"{id}\" refers to itself through <ref>s"),
            ))
        }
    }

    /// Marks `id` as read.
    pub fn done_reading(&mut self, id: &str) {
        self.reading.remove(id);
    }

    /// The file a property of `node` names: looked up in the `<path>` folders, then next to
    /// the file `node` is written in, then next to the scene file.
    pub fn resolve_file(&self, node: &Element, name: &str) -> PathBuf {
        let own_folder = match node.position.file.as_deref() {
            Some(file) => file.parent().map(Path::to_path_buf).unwrap_or_default(),
            None => self
                .file
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_default(),
        };
        resolve_file(name, &folders_for(self.search_folders, own_folder))
    }
}
