//! Chapter 5 and Sec. 6.1.4: shape functions, weight functions, parametrizations (issue 5).
