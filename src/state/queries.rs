//! Occlusion queries (§4.1.7, §6.1.12): query objects and the active GL_SAMPLES_PASSED query.
//! There is no rasterizer, so no sample ever passes: the counter has 0 bits, which §6.1.12
//! allows ("the counter contains no useful information"), and every result is 0.

use std::collections::{BTreeSet, HashSet};

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The query objects of a context.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QueryObjects {
    objects: HashSet<u32>,
    reserved: BTreeSet<u32>,
    /// The query active for GL_SAMPLES_PASSED, 0 if none.
    pub active: u32,
}

/// GL_INVALID_ENUM unless `target` is GL_SAMPLES_PASSED, GL 1.5's only query target.
fn check_target(target: GLenum) -> GlResult {
    if target == GL_SAMPLES_PASSED {
        Ok(())
    } else {
        Err(GlError::InvalidEnum)
    }
}

impl QueryObjects {
    /// glGenQueries.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::queries::QueryObjects;
    /// let mut queries = QueryObjects::default();
    /// let ids = queries.generate(2);
    /// assert_eq!(ids.len(), 2);
    /// assert!(!queries.is_query(ids[0]));
    /// ```
    pub fn generate(&mut self, count: usize) -> Vec<u32> {
        super::names::generate(self.objects.iter().copied(), &mut self.reserved, count)
    }

    /// glIsQuery: a name becomes a query object when a query begins with it.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects};
    /// let mut queries = QueryObjects::default();
    /// queries.begin(GL_SAMPLES_PASSED, 4)?;
    /// assert!(queries.is_query(4));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_query(&self, id: u32) -> bool {
        self.objects.contains(&id)
    }

    /// glDeleteQueries of one name; deleting the active query ends it.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects};
    /// let mut queries = QueryObjects::default();
    /// queries.begin(GL_SAMPLES_PASSED, 4)?;
    /// queries.delete(4); // ends it
    /// assert_eq!(queries.target_parameter(GL_SAMPLES_PASSED, GL_CURRENT_QUERY)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn delete(&mut self, id: u32) {
        self.reserved.remove(&id);
        if self.objects.remove(&id) && self.active == id {
            self.active = 0;
        }
    }

    /// glBeginQuery, in Mesa's order of checks: target, id 0, a query already active.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects, GlError};
    /// let mut queries = QueryObjects::default();
    /// queries.begin(GL_SAMPLES_PASSED, 1)?;
    /// assert_eq!(queries.begin(GL_SAMPLES_PASSED, 2), Err(GlError::InvalidOperation)); // one at a time
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn begin(&mut self, target: GLenum, id: u32) -> GlResult {
        check_target(target)?;
        if id == 0 || self.active != 0 {
            return Err(GlError::InvalidOperation);
        }
        self.reserved.remove(&id);
        self.objects.insert(id);
        self.active = id;
        Ok(())
    }

    /// glEndQuery: GL_INVALID_OPERATION when no query is active.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects, GlError};
    /// let mut queries = QueryObjects::default();
    /// assert_eq!(queries.end(GL_SAMPLES_PASSED), Err(GlError::InvalidOperation));
    /// ```
    pub fn end(&mut self, target: GLenum) -> GlResult {
        check_target(target)?;
        if self.active == 0 {
            return Err(GlError::InvalidOperation);
        }
        self.active = 0;
        Ok(())
    }

    /// glGetQueryiv: GL_CURRENT_QUERY or GL_QUERY_COUNTER_BITS (0: see the module).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects};
    /// assert_eq!(QueryObjects::default().target_parameter(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn target_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<i32> {
        check_target(target)?;
        match pname {
            GL_CURRENT_QUERY => Ok(self.active as i32),
            GL_QUERY_COUNTER_BITS => Ok(0),
            _ => Err(GlError::InvalidEnum),
        }
    }

    /// glGetQueryObject{i,ui}v: GL_QUERY_RESULT (always 0) or GL_QUERY_RESULT_AVAILABLE
    /// (always true); GL_INVALID_OPERATION for a name that is no query or the active one.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::queries::QueryObjects};
    /// let mut queries = QueryObjects::default();
    /// queries.begin(GL_SAMPLES_PASSED, 1)?;
    /// queries.end(GL_SAMPLES_PASSED)?;
    /// assert_eq!(queries.object_parameter(1, GL_QUERY_RESULT_AVAILABLE)?, 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn object_parameter(&self, id: u32, pname: GLenum) -> GlResult<u32> {
        if !self.objects.contains(&id) || id == self.active {
            return Err(GlError::InvalidOperation);
        }
        match pname {
            GL_QUERY_RESULT => Ok(0),
            GL_QUERY_RESULT_AVAILABLE => Ok(GL_TRUE as u32),
            _ => Err(GlError::InvalidEnum),
        }
    }
}
