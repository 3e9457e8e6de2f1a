plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":extension-api"))
    testImplementation(project(":kernel"))
}
