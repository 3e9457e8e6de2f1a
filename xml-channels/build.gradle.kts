plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":extension-api"))
    implementation(libs.jackson.dataformat.xml)
    implementation(libs.jackson.module.parameter.names)
    implementation(libs.ktor.network)
    testImplementation(project(":kernel"))
}
