//! Display lists (§5.4): glGenLists, glNewList, glEndList, glCallList, glCallLists,
//! glListBase, glDeleteLists, glIsList, and the recorded commands.
//!
//! A display list is data: one [`Command`] per compiled call, holding its arguments (the
//! values its pointers gave at compile time), and [`Command::execute`] calls the same
//! `Context` method the C entry point calls, so a list replays exactly as the calls would.
//! The entry points made from src/capi/entry_points.txt record a [`TableCommand`] (a line
//! marked `list`); the hand-written ones (vertex attributes, raster position, vertex-array
//! draws, glCallLists) record their own variants. Errors of a compiled command are raised
//! when the list executes, never at compile time (as Mesa does): a command whose arguments
//! cannot be read records its error ([`Command::Error`]).

use std::collections::HashMap;
use std::sync::Arc;

use glam::{Vec3, Vec4};

pub use crate::capi::TableCommand;
use crate::commands::arrays::{ArrayElementValues, RecordedDraw};
use crate::commands::texture::{SubImageArgs, TexImageArgs};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::pixel::PixelStoreModes;

/// GL_MAX_LIST_NESTING (Mesa's value): calls nested deeper are ignored.
pub const MAX_LIST_NESTING: usize = 64;

/// The most names one glGenLists reserves (a larger range returns 0, as when no block of
/// unused names is left).
const MAX_LIST_RANGE: u32 = 1 << 20;

/// One command of a display list.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// A command of the entry-point table.
    Table(TableCommand),
    /// A command whose arguments failed its checks at compile time: the error, raised when
    /// the list executes.
    Error(GlError),
    /// glColor (every form, converted to floats at compile time).
    Color(Vec4),
    /// glNormal.
    Normal(Vec3),
    /// glTexCoord.
    TexCoord(Vec4),
    /// glEdgeFlag.
    EdgeFlag(bool),
    /// glVertex.
    Vertex(Vec4),
    /// glRasterPos.
    RasterPos(Vec4),
    /// glCallLists: its offsets, decoded at compile time; the list base is the one in force
    /// when the list executes.
    CallLists(Vec<u32>),
    /// glArrayElement: the element's values, read at compile time.
    ArrayElement(ArrayElementValues),
    /// glDrawArrays, glDrawElements, glDrawRangeElements: the elements, read at compile time.
    Draw(Box<RecordedDraw>),
    /// glTexImage, glTexSubImage, glPolygonStipple: the image's bytes and the unpack modes in
    /// force at compile time, so it unpacks as it would have then (§5.4).
    Image(Box<RecordedImage>),
}

/// An image command of a display list.
#[derive(Clone, Debug, PartialEq)]
pub enum ImageCommand {
    /// glTexImage1D/2D/3D: the dimension count and the arguments.
    TexImage(usize, TexImageArgs),
    /// glTexSubImage1D/2D/3D: the dimension count and the arguments.
    TexSubImage(usize, SubImageArgs),
    /// glPolygonStipple.
    PolygonStipple,
}

/// An image command with its client bytes and the unpack modes they were given under.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedImage {
    /// Which command.
    pub command: ImageCommand,
    /// The unpack modes in force at compile time.
    pub unpack: PixelStoreModes,
    /// The client bytes the command read at compile time.
    pub bytes: Vec<u8>,
}

impl ImageCommand {
    /// Runs the command on `bytes` with the current unpack modes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::ImageCommand, Context};
    /// let mut ctx = Context::new();
    /// ImageCommand::PolygonStipple.run(&mut ctx, &[0u8; 128])?;
    /// let mut back = [1u8; 128];
    /// ctx.get_polygon_stipple(&mut back)?;
    /// assert_eq!(back, [0; 128]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn run(&self, ctx: &mut Context, bytes: &[u8]) -> GlResult {
        match self {
            ImageCommand::TexImage(dimensions, args) => ctx.tex_image(*dimensions, args, bytes),
            ImageCommand::TexSubImage(dimensions, args) => {
                ctx.tex_sub_image(*dimensions, args, bytes)
            }
            ImageCommand::PolygonStipple => ctx.polygon_stipple(bytes),
        }
    }
}

impl Context {
    /// Runs an image command now, or records it with a copy of `bytes` and the unpack modes
    /// while a list is being compiled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::ImageCommand, gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(1, GL_COMPILE)?;
    /// ctx.run_image_command(ImageCommand::PolygonStipple, &[0u8; 128])?; // recorded with its bytes
    /// ctx.end_list()?;
    /// let mut stipple = [0u8; 128];
    /// ctx.get_polygon_stipple(&mut stipple)?;
    /// assert_eq!(stipple, [0xff; 128]); // not run yet
    /// ctx.call_list(1)?;
    /// ctx.get_polygon_stipple(&mut stipple)?;
    /// assert_eq!(stipple, [0; 128]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn run_image_command(&mut self, command: ImageCommand, bytes: &[u8]) -> GlResult {
        let unpack = self.pixel_store.unpack.clone();
        if self.record(|| {
            Command::Image(Box::new(RecordedImage {
                command: command.clone(),
                unpack,
                bytes: bytes.to_vec(),
            }))
        }) {
            return Ok(());
        }
        command.run(self, bytes)
    }
}

impl From<TableCommand> for Command {
    fn from(command: TableCommand) -> Command {
        Command::Table(command)
    }
}

impl Command {
    /// Runs the command as its entry point would.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::Command, gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// Command::Color(glam::Vec4::new(0.0, 1.0, 0.0, 1.0)).execute(&mut ctx)?;
    /// assert_eq!(ctx.get(GL_CURRENT_COLOR)?.as_floats(), [0.0, 1.0, 0.0, 1.0]);
    /// assert_eq!(Command::Error(GlError::InvalidValue).execute(&mut ctx), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn execute(&self, ctx: &mut Context) -> GlResult {
        match self {
            Command::Table(command) => command.execute(ctx),
            Command::Error(error) => Err(*error),
            Command::Color(color) => {
                ctx.color(*color);
                Ok(())
            }
            Command::Normal(normal) => {
                ctx.normal(*normal);
                Ok(())
            }
            Command::TexCoord(tex_coord) => {
                ctx.tex_coord(*tex_coord);
                Ok(())
            }
            Command::EdgeFlag(flag) => {
                ctx.edge_flag(*flag);
                Ok(())
            }
            Command::Vertex(position) => {
                ctx.vertex(*position);
                Ok(())
            }
            Command::RasterPos(position) => ctx.raster_pos(*position),
            Command::CallLists(offsets) => {
                ctx.call_list_offsets(offsets);
                Ok(())
            }
            Command::ArrayElement(element) => {
                ctx.apply_array_element(element);
                Ok(())
            }
            Command::Draw(draw) => ctx.draw_recorded(draw),
            Command::Image(image) => {
                let current = std::mem::replace(&mut ctx.pixel_store.unpack, image.unpack.clone());
                let result = image.command.run(ctx, &image.bytes);
                ctx.pixel_store.unpack = current;
                result
            }
        }
    }
}

/// The list being compiled.
#[derive(Clone, Debug)]
struct Compiling {
    name: u32,
    mode: GLenum,
    commands: Vec<Command>,
}

/// The display lists of a context and the state of §5.4.
#[derive(Clone, Debug, Default)]
pub struct DisplayLists {
    lists: HashMap<u32, Arc<[Command]>>,
    /// One past the largest name ever used: where glGenLists looks first (Mesa's choice).
    next_name: u64,
    compiling: Option<Compiling>,
    /// GL_LIST_BASE.
    pub base: u32,
    /// How many lists are executing, one inside the other.
    depth: usize,
}

impl DisplayLists {
    /// GL_LIST_INDEX: the list being compiled, 0 for none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.display_lists().index(), 0);
    /// ctx.new_list(3, GL_COMPILE)?;
    /// assert_eq!(ctx.display_lists().index(), 3);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn index(&self) -> u32 {
        self.compiling.as_ref().map_or(0, |c| c.name)
    }

    /// GL_LIST_MODE: the mode of the list being compiled, 0 for none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(3, GL_COMPILE_AND_EXECUTE)?;
    /// assert_eq!(ctx.display_lists().mode(), GL_COMPILE_AND_EXECUTE);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn mode(&self) -> GLenum {
        self.compiling.as_ref().map_or(0, |c| c.mode)
    }

    /// The commands of list `name`, if it exists.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::Command, gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(2, GL_COMPILE)?;
    /// ctx.record_or_run(Command::EdgeFlag(false))?;
    /// ctx.end_list()?;
    /// assert_eq!(ctx.display_lists().get(2), Some(&[Command::EdgeFlag(false)][..]));
    /// assert_eq!(ctx.display_lists().get(3), None);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, name: u32) -> Option<&[Command]> {
        self.lists.get(&name).map(|list| &list[..])
    }

    fn define(&mut self, name: u32, commands: Arc<[Command]>) {
        self.lists.insert(name, commands);
        self.next_name = self.next_name.max(u64::from(name) + 1);
    }

    /// The first of `count` contiguous unused names: after the largest name ever used if
    /// they fit there, else the first gap that holds them.
    fn free_block(&self, count: u32) -> Option<u32> {
        let fits = |first: u64| first + u64::from(count) - 1 <= u64::from(u32::MAX);
        let first = self.next_name.max(1);
        if fits(first) {
            return Some(first as u32);
        }
        let mut used: Vec<u32> = self.lists.keys().copied().collect();
        used.sort_unstable();
        let mut candidate = 1u64;
        for name in used {
            if u64::from(name) >= candidate + u64::from(count) {
                break;
            }
            candidate = candidate.max(u64::from(name) + 1);
        }
        fits(candidate).then_some(candidate as u32)
    }
}

/// Bytes per name of glCallLists' `type`; `None` for a type it does not take.
///
/// # Examples
///
/// ```
/// use fflight::{commands::list::call_lists_type_size, gl::*};
/// assert_eq!(call_lists_type_size(GL_3_BYTES), Some(3));
/// assert_eq!(call_lists_type_size(GL_DOUBLE), None);
/// ```
pub fn call_lists_type_size(list_type: GLenum) -> Option<usize> {
    match list_type {
        GL_BYTE | GL_UNSIGNED_BYTE => Some(1),
        GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => Some(2),
        GL_3_BYTES => Some(3),
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => Some(4),
        _ => None,
    }
}

/// How many bytes glCallLists reads: 0 where its arguments define none.
///
/// # Examples
///
/// ```
/// use fflight::{commands::list::call_lists_bytes, gl::*};
/// assert_eq!(call_lists_bytes(5, GL_SHORT), 10);
/// assert_eq!(call_lists_bytes(-1, GL_SHORT), 0);
/// ```
pub fn call_lists_bytes(n: i32, list_type: GLenum) -> usize {
    call_lists_type_size(list_type).unwrap_or(0) * usize::try_from(n).unwrap_or(0)
}

/// One offset of glCallLists from its bytes (native byte order for the typed ones; the
/// GL_n_BYTES ones are big-endian, §5.4). Floats are truncated.
fn decode_offset(list_type: GLenum, b: &[u8]) -> u32 {
    match list_type {
        GL_BYTE => b[0] as i8 as u32,
        GL_UNSIGNED_BYTE => u32::from(b[0]),
        GL_SHORT => i16::from_ne_bytes([b[0], b[1]]) as u32,
        GL_UNSIGNED_SHORT => u32::from(u16::from_ne_bytes([b[0], b[1]])),
        GL_INT | GL_UNSIGNED_INT => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
        GL_FLOAT => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i32 as u32,
        _ => b
            .iter()
            .fold(0u32, |offset, &byte| (offset << 8) | u32::from(byte)),
    }
}

impl Context {
    /// The display lists.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(4, GL_COMPILE)?;
    /// assert_eq!((ctx.display_lists().index(), ctx.display_lists().mode()), (4, GL_COMPILE));
    /// ctx.end_list()?;
    /// assert_eq!(ctx.display_lists().get(4), Some(&[][..]));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn display_lists(&self) -> &DisplayLists {
        &self.lists
    }

    /// Whether a list is being compiled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert!(!ctx.compiling_list());
    /// ctx.new_list(1, GL_COMPILE)?;
    /// assert!(ctx.compiling_list());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn compiling_list(&self) -> bool {
        self.lists.compiling.is_some()
    }

    /// While a list is being compiled, appends the command `make` builds to it. Returns true
    /// when the command must not also run now (GL_COMPILE); false when it runs (not
    /// compiling, or GL_COMPILE_AND_EXECUTE). Every compiled entry point calls this first.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::Command, gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(1, GL_COMPILE)?;
    /// assert!(ctx.record(|| Command::EdgeFlag(false))); // recorded, not to be run
    /// ctx.end_list()?;
    /// assert!(!ctx.record(|| Command::EdgeFlag(false))); // not compiling: run it
    /// assert_eq!(ctx.display_lists().get(1).map(<[_]>::len), Some(1));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn record(&mut self, make: impl FnOnce() -> Command) -> bool {
        match &mut self.lists.compiling {
            None => false,
            Some(list) => {
                list.commands.push(make());
                list.mode == GL_COMPILE
            }
        }
    }

    /// `record` for a command built from the application's data, whose checks may fail:
    /// their error is recorded in its place (raised when the list executes).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::Command, gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.new_list(1, GL_COMPILE)?;
    /// // A check that fails at compile time is recorded as its error.
    /// assert!(ctx.record_checked(|_| Err(GlError::InvalidValue)));
    /// ctx.end_list()?;
    /// assert_eq!(ctx.display_lists().get(1), Some(&[Command::Error(GlError::InvalidValue)][..]));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn record_checked(&mut self, make: impl FnOnce(&Context) -> GlResult<Command>) -> bool {
        if !self.compiling_list() {
            return false;
        }
        let command = make(self).unwrap_or_else(Command::Error);
        self.record(|| command)
    }

    /// Records `command` while compiling, and runs it unless the mode is GL_COMPILE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::list::Command, gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.record_or_run(Command::Normal(glam::Vec3::X))?; // not compiling: runs
    /// assert_eq!(ctx.get(GL_CURRENT_NORMAL)?.as_floats(), [1.0, 0.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn record_or_run(&mut self, command: Command) -> GlResult {
        if self.record(|| command.clone()) {
            return Ok(());
        }
        command.execute(self)
    }

    /// glNewList, in Mesa's order of checks.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{capi::TableCommand, gl::*, Context};
    /// let mut ctx = Context::new();
    /// let list = ctx.gen_lists(1)?;
    /// ctx.new_list(list, GL_COMPILE)?;
    /// assert!(ctx.compiling_list());
    /// // The C entry points record themselves; from Rust, record the command.
    /// ctx.record_or_run(TableCommand::glEnable { cap: GL_LIGHTING }.into())?;
    /// ctx.end_list()?;
    /// assert!(!ctx.is_enabled(GL_LIGHTING)?); // compiled, not run
    /// ctx.call_list(list)?;
    /// assert!(ctx.is_enabled(GL_LIGHTING)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new_list(&mut self, name: u32, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if name == 0 {
            return Err(GlError::InvalidValue);
        }
        if mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE {
            return Err(GlError::InvalidEnum);
        }
        if self.compiling_list() {
            return Err(GlError::InvalidOperation);
        }
        self.lists.compiling = Some(Compiling {
            name,
            mode,
            commands: Vec::new(),
        });
        Ok(())
    }

    /// glEndList: only now does the list replace the one of its name.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.end_list(), Err(GlError::InvalidOperation)); // no list being compiled
    /// ctx.new_list(1, GL_COMPILE_AND_EXECUTE)?;
    /// assert_eq!(ctx.get(GL_LIST_INDEX)?.as_ints(), [1]);
    /// ctx.end_list()?;
    /// assert!(ctx.is_list(1)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn end_list(&mut self) -> GlResult {
        self.outside_begin_end()?;
        let list = self
            .lists
            .compiling
            .take()
            .ok_or(GlError::InvalidOperation)?;
        self.lists.define(list.name, list.commands.into());
        Ok(())
    }

    /// glGenLists: `range` contiguous unused names, each made an empty list; 0 when there
    /// is no such block or `range` is 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let mut ctx = Context::new();
    /// let first = ctx.gen_lists(3)?;
    /// assert!(first > 0 && ctx.is_list(first + 2)?);
    /// assert_eq!(ctx.gen_lists(0)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn gen_lists(&mut self, range: i32) -> GlResult<u32> {
        self.outside_begin_end()?;
        let count = u32::try_from(range).map_err(|_| GlError::InvalidValue)?;
        if count == 0 {
            return Ok(0);
        }
        // §5.4: 0 when no group of `range` unused names is available; fflight reserves at most
        // MAX_LIST_RANGE names a call (each reserved name is an empty list), so a huge range
        // gets 0 at once instead of minutes of work.
        if count > MAX_LIST_RANGE {
            return Ok(0);
        }
        let Some(first) = self.lists.free_block(count) else {
            return Ok(0);
        };
        for name in first..=first + (count - 1) {
            self.lists.define(name, Arc::new([]));
        }
        Ok(first)
    }

    /// glDeleteLists: names without a list are ignored.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let mut ctx = Context::new();
    /// let first = ctx.gen_lists(2)?;
    /// ctx.delete_lists(first, 2)?;
    /// assert!(!ctx.is_list(first)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn delete_lists(&mut self, first: u32, range: i32) -> GlResult {
        self.outside_begin_end()?;
        let count = u64::try_from(range).map_err(|_| GlError::InvalidValue)?;
        let names = u64::from(first)..u64::from(first) + count;
        if count > self.lists.lists.len() as u64 {
            self.lists
                .lists
                .retain(|&name, _| !names.contains(&u64::from(name)));
        } else {
            for name in names {
                if let Ok(name) = u32::try_from(name) {
                    self.lists.lists.remove(&name);
                }
            }
        }
        Ok(())
    }

    /// glIsList.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let ctx = Context::new();
    /// assert!(!ctx.is_list(1)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_list(&self, name: u32) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.lists.lists.contains_key(&name))
    }

    /// glListBase.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.list_base(100)?;
    /// assert_eq!(ctx.get(GL_LIST_BASE)?.as_ints(), [100]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn list_base(&mut self, base: u32) -> GlResult {
        self.outside_begin_end()?;
        self.lists.base = base;
        Ok(())
    }

    /// glCallList: legal between glBegin and glEnd (§2.6.3); a name without a list does
    /// nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let mut ctx = Context::new();
    /// ctx.call_list(42)?; // no such list: nothing happens
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn call_list(&mut self, name: u32) -> GlResult {
        if name == 0 {
            return Err(GlError::InvalidValue);
        }
        self.execute_list(name);
        Ok(())
    }

    /// glCallLists' checks and offsets, from the `lists` bytes of its `n` names of
    /// `list_type` (GL_INVALID_ENUM for a bad type, even when `n` is 0, as Mesa).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// // Two GL_UNSIGNED_SHORT names, in native byte order.
    /// let bytes: Vec<u8> = [3u16, 5].iter().flat_map(|n| n.to_ne_bytes()).collect();
    /// assert_eq!(ctx.call_lists_offsets(2, GL_UNSIGNED_SHORT, &bytes)?, [3, 5]);
    /// assert_eq!(ctx.call_lists_offsets(0, GL_DOUBLE, &[]), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn call_lists_offsets(
        &self,
        n: i32,
        list_type: GLenum,
        lists: &[u8],
    ) -> GlResult<Vec<u32>> {
        let size = call_lists_type_size(list_type).ok_or(GlError::InvalidEnum)?;
        let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        if n > 0 && lists.len() < n * size {
            return Err(GlError::InvalidValue); // NULL
        }
        Ok(lists
            .chunks_exact(size)
            .take(n)
            .map(|bytes| decode_offset(list_type, bytes))
            .collect())
    }

    /// glCallLists.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{capi::TableCommand, gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.new_list(11, GL_COMPILE)?;
    /// ctx.record_or_run(TableCommand::glEnable { cap: GL_NORMALIZE }.into())?;
    /// ctx.end_list()?;
    /// ctx.list_base(10)?;
    /// ctx.call_lists(1, GL_UNSIGNED_BYTE, &[1])?; // list 10 + 1
    /// assert!(ctx.is_enabled(GL_NORMALIZE)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn call_lists(&mut self, n: i32, list_type: GLenum, lists: &[u8]) -> GlResult {
        let offsets = self.call_lists_offsets(n, list_type, lists)?;
        self.call_list_offsets(&offsets);
        Ok(())
    }

    /// Executes the lists `base + offset` for each offset, with the list base in force.
    pub(crate) fn call_list_offsets(&mut self, offsets: &[u32]) {
        for &offset in offsets {
            self.execute_list(self.lists.base.wrapping_add(offset));
        }
    }

    /// Runs the commands of list `name`, each error recorded as the command raises it;
    /// nothing when the list does not exist or GL_MAX_LIST_NESTING lists already execute.
    fn execute_list(&mut self, name: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(commands) = self.lists.lists.get(&name).cloned() else {
            return;
        };
        self.lists.depth += 1;
        for command in commands.iter() {
            if let Err(error) = command.execute(self) {
                self.record_error(error);
            }
        }
        self.lists.depth -= 1;
    }
}
