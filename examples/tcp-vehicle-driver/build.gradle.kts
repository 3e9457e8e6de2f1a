plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":kernel"))
}
