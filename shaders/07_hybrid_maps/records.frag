#version 410 core
// Writes the record its point carries (records.vert).
flat in uvec4 vRecord;
layout(location = 0) out uvec4 outRecord;
void main() { outRecord = vRecord; }
