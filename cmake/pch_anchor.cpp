// Empty translation unit: the target that owns the tests' shared
// precompiled header needs one source file (see FacadeslamTargets.cmake).
