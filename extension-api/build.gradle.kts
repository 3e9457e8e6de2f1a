plugins {
    id("ktcs.kotlin-jvm")
}

kotlin {
    explicitApi()
}

// api(...) plays Maven's compile scope: an extension that builds on this module sees these too.
dependencies {
    api(project(":api"))
    api(libs.koin.core)
    api(libs.ktor.server.core)
}
