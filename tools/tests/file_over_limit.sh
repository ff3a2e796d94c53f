#!/bin/sh
# collide query refuses a scene file larger than its 64 MiB limit (TOOL_MAX_FILE_BYTES): a valid
# scene followed by 64 MiB + 100 bytes of spaces must exit 2 with "larger than 64 MiB" (the limit
# was checked before the buffer doubled, so files up to 128 MiB loaded). A file of exactly the
# limit still loads.
# Usage: sh file_over_limit.sh path/to/collide scratch-file
tool=$1
file=$2
scene='{"name": "s", "dimension": 2, "shapes": [{"name": "c", "type": "circle", "center": [0, 0], "radius": 1}]}'
{ printf '%s\n' "$scene"; head -c 67108964 /dev/zero | tr '\0' ' '; } > "$file"
"$tool" query "$file" > /dev/null 2> "$file.err"
status=$?
if [ "$status" -ne 2 ] || ! grep -q "larger than 64 MiB" "$file.err"; then
	echo "over the limit: expected exit 2 and 'larger than 64 MiB', got exit $status: $(cat "$file.err")"
	rm -f "$file" "$file.err"
	exit 1
fi
size=$(printf '%s\n' "$scene" | wc -c)
{ printf '%s\n' "$scene"; head -c $((67108864 - size)) /dev/zero | tr '\0' ' '; } > "$file"
"$tool" query "$file" > /dev/null 2> "$file.err"
status=$?
rm -f "$file" "$file.err"
if [ "$status" -ne 0 ]; then
	echo "exactly the limit: expected exit 0, got $status"
	exit 1
fi
echo "file limit: over refused, exactly the limit loaded"
