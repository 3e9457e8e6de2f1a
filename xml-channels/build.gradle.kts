plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":extension-api"))
    implementation(libs.jackson.dataformat.xml)
    implementation(libs.jackson.module.kotlin)
    implementation(libs.ktor.network)
    testImplementation(project(":kernel"))
}
