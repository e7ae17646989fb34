//! The state of reading one scene file: where we are, the `$name` parameters, the BSDFs
//! that `<ref>` can name, and the warnings gathered so far.

use std::collections::HashMap;
use std::path::Path;

use roxmltree::{Document, Node};

use super::error::{SceneError, SceneWarning, TextPosition};
use super::values::{parse_float, parse_vec3, substitute};
use crate::scene::Material;
use glam::Vec3;

/// Reads attributes with `$name` substitution and turns problems into located errors.
pub(super) struct Reader<'a, 'input> {
    /// The scene file, for messages and relative paths.
    pub file: &'a Path,
    document: &'a Document<'input>,
    parameters: HashMap<String, String>,
    /// BSDFs with an `id`, by id, for `<ref>`.
    pub bsdfs_by_id: HashMap<String, Material>,
    /// Ignored things worth telling the user about.
    pub warnings: Vec<SceneWarning>,
}

impl<'a, 'input> Reader<'a, 'input> {
    /// A reader with the given `$name` parameters (defaults already overridden).
    pub fn new(
        file: &'a Path,
        document: &'a Document<'input>,
        parameters: HashMap<String, String>,
    ) -> Self {
        Reader {
            file,
            document,
            parameters,
            bsdfs_by_id: HashMap::new(),
            warnings: Vec::new(),
        }
    }

    /// Where `node` starts in the file.
    pub fn position(&self, node: Node) -> TextPosition {
        let position = self.document.text_pos_at(node.range().start);
        TextPosition {
            line: position.row,
            column: position.col,
        }
    }

    /// An error at `position`.
    pub fn error_at(&self, position: TextPosition, message: impl Into<String>) -> SceneError {
        SceneError {
            file: self.file.to_path_buf(),
            line: position.line,
            column: position.column,
            message: message.into(),
        }
    }

    /// An error at the start of `node`.
    pub fn error(&self, node: Node, message: impl Into<String>) -> SceneError {
        self.error_at(self.position(node), message)
    }

    /// Records a warning at `position`.
    pub fn warn_at(&mut self, position: TextPosition, message: impl Into<String>) {
        self.warnings.push(SceneWarning {
            file: self.file.to_path_buf(),
            line: position.line,
            column: position.column,
            message: message.into(),
        });
    }

    /// The attribute `name` of `node` with `$name`s substituted, if present.
    pub fn attribute(&self, node: Node, name: &str) -> Result<Option<String>, SceneError> {
        match node.attribute(name) {
            None => Ok(None),
            Some(raw) => substitute(raw, &self.parameters)
                .map(Some)
                .map_err(|message| self.error(node, message)),
        }
    }

    /// The attribute `name` of `node`, which must be present.
    pub fn required_attribute(&self, node: Node, name: &str) -> Result<String, SceneError> {
        self.attribute(node, name)?.ok_or_else(|| {
            let tag = node.tag_name().name();
            self.error(node, format!("<{tag}> needs a \"{name}\" attribute"))
        })
    }

    /// Parses the attribute `name` of `node` with `parse`, locating any error at `node`.
    pub fn parsed_attribute<T>(
        &self,
        node: Node,
        name: &str,
        parse: impl Fn(&str) -> Result<T, String>,
    ) -> Result<Option<T>, SceneError> {
        match self.attribute(node, name)? {
            None => Ok(None),
            Some(text) => parse(&text).map(Some).map_err(|message| {
                let tag = node.tag_name().name();
                self.error(node, format!("attribute \"{name}\" of <{tag}>: {message}"))
            }),
        }
    }

    /// A point or vector written as `value="x, y, z"` or as `x`, `y`, `z` attributes of
    /// `node` (each 0 when left out).
    pub fn xyz(&self, node: Node) -> Result<Vec3, SceneError> {
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
}
