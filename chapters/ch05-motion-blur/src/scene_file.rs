//! Scenes from Mitsuba 3 XML files.
