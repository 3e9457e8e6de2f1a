plugins {
    id("ktcs.kotlin-jvm")
}

kotlin {
    explicitApi()
}

// api(...) plays Maven's compile scope: these reach every module that builds on this one.
dependencies {
    api(libs.kotlinx.coroutines.core)
}
