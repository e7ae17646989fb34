//! The scene's element tree: the scene file and every file it includes, read into one tree
//! whose elements remember the file, line and column they were written at.
//!
//! Mitsuba 3 reads a scene as one document although it may be spread over several files:
//! `<include filename="..."/>` puts the children of another file's `<scene>` where the include
//! stands, and `<path value="..."/>` adds a folder in which files named later are looked for.
//! Building the whole tree first lets the reader that follows look up any `id` in it, so an
//! object may be referenced before the line that declares it, as Mitsuba allows.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use roxmltree::{Document, ParsingOptions};

use super::bounded_read::{SCENE_FILE_LIMIT, read_text};
use super::error::{SceneError, TextPosition};
use super::values::substitute;

mod upgrade;

/// How deep includes may nest before the loader assumes a file includes itself.
const MAX_INCLUDE_DEPTH: usize = 16;

/// How deep elements may nest in one file. A scene nests a handful of levels (a shape, its
/// two-sided BSDF, a blend, a texture); a file nested thousands deep is hostile, and the tree
/// is built and walked recursively, so it is refused before it is built. With includes the
/// whole tree nests at most `MAX_INCLUDE_DEPTH` times as deep.
const MAX_NESTING: usize = 100;

/// How many XML nodes (elements, and the text and comments between them) a scene may hold with
/// all its includes. A scene of thousands of shapes holds some tens of thousands; without a
/// bound, a file that includes another a thousand times, which includes a third a thousand
/// times, and so on, would grow as the product of its fan-outs, each level under the size
/// limit of one file. Each file is parsed with what is left of the bound, so parsing stops
/// where it is reached, before the memory is taken.
pub(super) const MAX_NODES: u32 = 4_000_000;

/// How many files a scene may include in all (the same file counted each time it is
/// included). A scene includes a few; reading a file takes a millisecond, so a file of a
/// million includes of an empty file would take many minutes, within the bound on nodes.
const MAX_INCLUDES: u32 = 10_000;

/// One XML element with its attributes as written (`$name`s not yet substituted).
#[derive(Clone, Debug)]
pub(super) struct Element {
    name: String,
    attributes: Vec<(String, String)>,
    children: Vec<Element>,
    /// Where the element starts; its `file` is `None` in the scene file itself.
    pub position: TextPosition,
}

impl Element {
    /// The tag, such as `shape`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Whether the tag is `name`.
    pub fn has_name(&self, name: &str) -> bool {
        self.name == name
    }

    /// The attribute `name` as written.
    pub fn attribute(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(key, _)| key == name)
            .map(|(_, value)| value.as_str())
    }

    /// The child elements, in file order.
    pub fn children(&self) -> impl Iterator<Item = &Element> {
        self.children.iter()
    }

    /// This element and every element below it, depth first.
    fn walk<'a>(&'a self, visit: &mut impl FnMut(&'a Element)) {
        visit(self);
        for child in &self.children {
            child.walk(visit);
        }
    }
}

/// A scene's elements with the folders its file names are looked up in.
#[derive(Debug)]
pub(super) struct SceneTree {
    /// The `<scene>` element, includes expanded.
    pub root: Element,
    /// The `$name` parameters: the caller's overrides, then every `<default>` not overridden
    /// (the first declaration of a name wins, as in Mitsuba 3).
    pub parameters: HashMap<String, String>,
    /// Folders from `<path>` elements, most recent first, then the scene file's folder.
    pub search_folders: Vec<PathBuf>,
}

impl SceneTree {
    /// Every object with an `id` attribute, by id (a `<ref>`'s `id` names another object and
    /// is not counted); an id given twice is an error.
    pub fn elements_by_id(&self, file: &Path) -> Result<HashMap<String, &Element>, SceneError> {
        let mut by_id: HashMap<String, &Element> = HashMap::new();
        let mut duplicate = None;
        self.root.walk(&mut |element| {
            let Some(raw) = element.attribute("id").filter(|_| !element.has_name("ref")) else {
                return;
            };
            let id = substitute(raw, &self.parameters).unwrap_or_else(|_| raw.to_string());
            if let Some(first) = by_id.insert(id.clone(), element)
                && duplicate.is_none()
            {
                duplicate = Some((element, first.position.clone(), id));
            }
        });
        match duplicate {
            None => Ok(by_id),
            Some((element, first, id)) => Err(SceneError::at(
                file,
                &element.position,
                format!("the id \"{id}\" is already used by the element at {first}"),
            )),
        }
    }
}

/// Reads the scene file `text` (named `file`) and every file it includes into one tree.
pub(super) fn read_tree(
    text: &str,
    file: &Path,
    overrides: &[(String, String)],
) -> Result<SceneTree, SceneError> {
    let mut builder = TreeBuilder {
        scene_file: file,
        parameters: overrides.iter().cloned().collect(),
        search_folders: vec![folder_of(file)],
        include_chain: Vec::new(),
        nodes_left: MAX_NODES,
        includes_read: 0,
    };
    let root = builder.read_file(text, None)?;
    Ok(SceneTree {
        root,
        parameters: builder.parameters,
        search_folders: builder.search_folders,
    })
}

/// The folder a file is in: empty for a bare file name, so that names joined to it stay as
/// the user would write them.
fn folder_of(file: &Path) -> PathBuf {
    file.parent().map(Path::to_path_buf).unwrap_or_default()
}

/// Looks `name` up: as written when absolute, else in each folder in turn; the first that
/// exists wins. When none has it, the first folder's candidate is returned, so that reading it
/// fails with a message naming a path the user can check.
pub(super) fn resolve_file(name: &str, folders: &[PathBuf]) -> PathBuf {
    let path = Path::new(name);
    if path.is_absolute() {
        return path.to_path_buf();
    }
    let candidates: Vec<PathBuf> = folders.iter().map(|folder| folder.join(path)).collect();
    candidates
        .iter()
        .find(|candidate| candidate.exists())
        .or(candidates.first())
        .cloned()
        .unwrap_or_else(|| path.to_path_buf())
}

/// Where a file named in an element is looked for, in order: the `<path>` folders, most
/// recent first (as Mitsuba puts them before the others), then the folder of the file the
/// element is written in, then the scene file's folder (the last of `search_folders`).
pub(super) fn folders_for(search_folders: &[PathBuf], own_folder: PathBuf) -> Vec<PathBuf> {
    let (scene_folder, paths) = search_folders
        .split_last()
        .map_or((None, search_folders), |(last, rest)| (Some(last), rest));
    let mut folders = paths.to_vec();
    folders.push(own_folder);
    folders.extend(scene_folder.cloned());
    folders
}

struct TreeBuilder<'a> {
    scene_file: &'a Path,
    parameters: HashMap<String, String>,
    search_folders: Vec<PathBuf>,
    /// The included files being read, outermost first, to refuse a file that includes itself.
    include_chain: Vec<PathBuf>,
    /// How many more XML nodes the scene may hold ([`MAX_NODES`] at the start).
    nodes_left: u32,
    /// How many includes have been read ([`MAX_INCLUDES`] at most).
    includes_read: u32,
}

impl TreeBuilder<'_> {
    /// The `<scene>` of one file; `included` is its path when it is not the scene file.
    fn read_file(
        &mut self,
        text: &str,
        included: Option<&Arc<Path>>,
    ) -> Result<Element, SceneError> {
        let file_for_errors = included.map_or(self.scene_file, |path| path);
        let options = ParsingOptions {
            nodes_limit: self.nodes_left,
            ..ParsingOptions::default()
        };
        let document = Document::parse_with_options(text, options).map_err(|error| {
            let position = error.pos();
            let message = match error {
                roxmltree::Error::NodesLimitReached => format!(
                    "the scene holds more than {MAX_NODES} XML nodes (elements, text and \
                     comments) with its includes when it gets here; the reader refuses larger \
                     scenes"
                ),
                _ => format!("malformed XML: {error}"),
            };
            SceneError {
                file: file_for_errors.to_path_buf(),
                line: position.row,
                column: position.col,
                message,
            }
        })?;
        let nodes = u32::try_from(document.descendants().count()).unwrap_or(u32::MAX);
        self.nodes_left = self.nodes_left.saturating_sub(nodes);
        if let Some(node) = first_too_deep(document.root_element()) {
            let position = document.text_pos_at(node.range().start);
            return Err(SceneError {
                file: file_for_errors.to_path_buf(),
                line: position.row,
                column: position.col,
                message: format!(
                    "elements nest more than {MAX_NESTING} levels deep here (a scene nests a \
                     handful); the reader refuses deeper files"
                ),
            });
        }
        let mut root = convert(&document, document.root_element(), included);
        if !root.has_name("scene") {
            let message = format!(
                "expected <scene> as the outer element, found <{}>",
                root.name
            );
            return Err(SceneError::at(self.scene_file, &root.position, message));
        }
        // A file written for Mitsuba 0.6 is upgraded as Mitsuba 3 upgrades it, before its
        // includes (which have versions of their own) are read in.
        if let Some(version) = root.attribute("version") {
            let old = upgrade::is_before_version_2(version)
                .map_err(|message| self.error(&root, message))?;
            if old {
                upgrade::upgrade_from_version_1(&mut root);
            }
        }
        let mut children = Vec::new();
        for child in root.children {
            match child.name() {
                "default" => {
                    self.declare_default(&child)?;
                    children.push(child);
                }
                "path" => self.add_search_folder(&child)?,
                "include" => children.extend(self.include(&child)?),
                _ => children.push(child),
            }
        }
        Ok(Element { children, ..root })
    }

    /// Records a `<default name="..." value="..."/>` unless the name is already set.
    fn declare_default(&mut self, element: &Element) -> Result<(), SceneError> {
        let (Some(name), Some(value)) = (element.attribute("name"), element.attribute("value"))
        else {
            return Err(self.error(element, "<default> needs \"name\" and \"value\" attributes"));
        };
        self.parameters
            .entry(name.to_string())
            .or_insert_with(|| value.to_string());
        Ok(())
    }

    /// `<path value="folder"/>`: the folder, relative to the file that names it, is searched
    /// first from now on.
    fn add_search_folder(&mut self, element: &Element) -> Result<(), SceneError> {
        let value = self.required(element, "value")?;
        let base = self.folder_of_element(element);
        self.search_folders.insert(0, base.join(value));
        Ok(())
    }

    /// The children of the `<scene>` in the file an `<include>` names.
    fn include(&mut self, element: &Element) -> Result<Vec<Element>, SceneError> {
        let name = self.required(element, "filename")?;
        let folders = folders_for(&self.search_folders, self.folder_of_element(element));
        let path = resolve_file(&name, &folders);
        if self.include_chain.contains(&path) {
            return Err(self.error(
                element,
                format!(
                    "the include of \"{name}\" makes a loop: {} is already being read",
                    path.display()
                ),
            ));
        }
        if self.includes_read >= MAX_INCLUDES {
            return Err(self.error(
                element,
                format!(
                    "the scene includes more than {MAX_INCLUDES} files in all (the same file \
                     counted each time); the reader refuses more"
                ),
            ));
        }
        self.includes_read += 1;
        if self.include_chain.len() >= MAX_INCLUDE_DEPTH {
            return Err(self.error(
                element,
                format!(
                    "the include of \"{name}\" would nest includes more than \
                     {MAX_INCLUDE_DEPTH} files deep; the reader refuses deeper chains"
                ),
            ));
        }
        let text = read_text(&path, "included file", SCENE_FILE_LIMIT)
            .map_err(|message| self.error(element, message))?;
        self.include_chain.push(path.clone());
        let included: Arc<Path> = Arc::from(path.as_path());
        let scene = self.read_file(&text, Some(&included));
        self.include_chain.pop();
        Ok(scene?.children)
    }

    /// The folder of the file `element` was written in.
    fn folder_of_element(&self, element: &Element) -> PathBuf {
        folder_of(element.position.file.as_deref().unwrap_or(self.scene_file))
    }

    /// The attribute `name`, `$name`s substituted with the parameters known so far.
    fn required(&self, element: &Element, name: &str) -> Result<String, SceneError> {
        let raw = element.attribute(name).ok_or_else(|| {
            self.error(
                element,
                format!("<{}> needs a \"{name}\" attribute", element.name),
            )
        })?;
        substitute(raw, &self.parameters).map_err(|message| self.error(element, message))
    }

    fn error(&self, element: &Element, message: impl Into<String>) -> SceneError {
        SceneError::at(self.scene_file, &element.position, message)
    }
}

/// The element `node` of `document` with its subtree, positions naming `file`.
/// The first element, in file order, nested deeper than [`MAX_NESTING`] below `root`, found
/// without recursion (the depth is what is not trusted).
fn first_too_deep<'a, 'input>(
    root: roxmltree::Node<'a, 'input>,
) -> Option<roxmltree::Node<'a, 'input>> {
    let mut stack = vec![(root, 0usize)];
    while let Some((node, depth)) = stack.pop() {
        if depth > MAX_NESTING {
            return Some(node);
        }
        let children: Vec<_> = node
            .children()
            .filter(roxmltree::Node::is_element)
            .collect();
        stack.extend(children.into_iter().rev().map(|child| (child, depth + 1)));
    }
    None
}

fn convert(document: &Document, node: roxmltree::Node, file: Option<&Arc<Path>>) -> Element {
    let start = document.text_pos_at(node.range().start);
    Element {
        name: node.tag_name().name().to_string(),
        attributes: node
            .attributes()
            .map(|attribute| (attribute.name().to_string(), attribute.value().to_string()))
            .collect(),
        children: node
            .children()
            .filter(roxmltree::Node::is_element)
            .map(|child| convert(document, child, file))
            .collect(),
        position: TextPosition {
            line: start.row,
            column: start.col,
            file: file.cloned(),
        },
    }
}
